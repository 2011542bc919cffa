#include "holefill/islands.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_set>

#include "holefill/stats.h"
#include "outline_grid.h"
#include "point_cloud_tree.h"

namespace holefill {
namespace {

using detail::cross2;
using detail::OutlineGrid;
using detail::Point2;

// A loop touches another when it comes this close to it, in the surrounding edge length.
constexpr double kTouchingFraction = 0.1;

// A hole's plane (through its centroid, normal to its vector area) and its outline there.
struct LoopPlane {
  Point centroid{0.0, 0.0, 0.0}, normal{0.0, 0.0, 0.0}, u{0.0, 0.0, 0.0}, v{0.0, 0.0, 0.0};
  double area = 0.0;    // of the outline
  double radius = 0.0;  // largest distance of a loop vertex from the centroid
  std::vector<Point2> outline;

  Point2 project(const Point& p) const {
    const Point d = p - centroid;
    return {OpenMesh::dot(d, u), OpenMesh::dot(d, v)};
  }
  double height(const Point& p) const { return OpenMesh::dot(p - centroid, normal); }
};

std::vector<Point> loop_points(const Mesh& mesh, const Hole& hole) {
  std::vector<Point> points;
  for (const auto v : hole.vertices) points.push_back(mesh.point(v));
  return points;
}

LoopPlane loop_plane(const std::vector<Point>& points, const Point& centroid) {
  LoopPlane plane;
  plane.centroid = centroid;
  Point vector_area(0.0, 0.0, 0.0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    vector_area +=
        OpenMesh::cross(points[i] - centroid, points[(i + 1) % points.size()] - centroid);
    plane.radius = std::max(plane.radius, (points[i] - centroid).norm());
  }
  plane.area = 0.5 * vector_area.norm();
  if (!(plane.area > 0.0)) return plane;
  plane.normal = vector_area.normalized();
  const Point axis = std::abs(plane.normal[0]) < 0.9 ? Point(1, 0, 0) : Point(0, 1, 0);
  plane.u = OpenMesh::cross(plane.normal, axis).normalized();
  plane.v = OpenMesh::cross(plane.normal, plane.u);
  for (const auto& p : points) plane.outline.push_back(plane.project(p));
  return plane;
}

// Every point of `inner` inside the outline `outer` files, and no edge of one crossing an edge of
// the other.
bool outline_inside(const std::vector<Point2>& inner, const OutlineGrid& outer) {
  for (const auto& p : inner) {
    if (!outer.contains(p)) return false;
  }
  for (std::size_t i = 0; i < inner.size(); ++i) {
    if (outer.crossed_by(inner[i], inner[(i + 1) % inner.size()])) return false;
  }
  return true;
}

double signed_area(const std::vector<Point2>& outline) {
  double twice = 0.0;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    twice += cross2({0.0, 0.0}, outline[i], outline[(i + 1) % outline.size()]);
  }
  return 0.5 * twice;
}

double distance_to_segment(const Point& p, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double length2 = ab.sqrnorm();
  const double t = length2 > 0.0 ? std::clamp(OpenMesh::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

// Some point of `inner` comes within `tolerance` of an edge of `outer` (in space: the grid, in
// outer's plane, only picks the edges whose projections come that close).
bool comes_within(const std::vector<Point>& inner, const std::vector<Point>& outer,
                  const LoopPlane& plane, const OutlineGrid& grid, double tolerance) {
  std::vector<int> edges;
  for (const auto& p : inner) {
    edges.clear();
    grid.edges_near(plane.project(p), tolerance, edges);
    for (const int j : edges) {
      const Point& a = outer[static_cast<std::size_t>(j)];
      const Point& b = outer[(static_cast<std::size_t>(j) + 1) % outer.size()];
      if (distance_to_segment(p, a, b) <= tolerance) return true;
    }
  }
  return false;
}

struct Loop {
  const Hole* hole;
  std::vector<Point> points;
  LoopPlane plane;
  int component;
};

// A hole with its outline filed (outline_grid.h): what relation() asks of it.
struct Outer {
  const Loop& loop;
  OutlineGrid grid;
  explicit Outer(const Loop& outer) : loop(outer), grid(outer.plane.outline) {}
};

enum class Relation { None, Island, Touching };

double touching_tolerance(const Loop& outer) {
  return kTouchingFraction * outer.hole->mean_surrounding_edge_length;
}

// `outline` (a loop projected onto outer's plane, at `heights` from it) lies inside outer's
// outline, clear of it, and within reach of the plane.
bool lies_inside(const Outer& outer, const std::vector<Point2>& outline,
                 const std::vector<double>& heights, const IslandOptions& options) {
  const LoopPlane& plane = outer.loop.plane;
  for (const double height : heights) {
    if (std::abs(height) > options.reach * plane.radius) return false;
  }
  // Clear of the outline, not on it: two stacked loops of the same shape are no island.
  const double tolerance = touching_tolerance(outer.loop);
  return outline_inside(outline, outer.grid) &&
         std::none_of(outline.begin(), outline.end(),
                      [&](const Point2& p) { return outer.grid.near(p, tolerance); });
}

void project(const Loop& outer, const Loop& loop, std::vector<Point2>& outline,
             std::vector<double>& heights) {
  for (const auto& p : loop.points) {
    outline.push_back(outer.plane.project(p));
    heights.push_back(outer.plane.height(p));
  }
}

bool shares_a_vertex(const Hole& a, const Hole& b) {
  std::unordered_set<int> ids;
  for (const auto v : a.vertices) ids.insert(v.idx());
  return std::any_of(b.vertices.begin(), b.vertices.end(),
                     [&](VertexHandle v) { return ids.count(v.idx()); });
}

// How loop `inner` relates to hole `outer` (see islands.h), leaving out the other loops of its
// component. Linear in the loops' lengths where the outlines are spread over the grid: a loop of
// the outer's own component that shares none of its vertices is ruled out before any outline is
// compared (a ring's two 200,000-edge loops took 118 s).
Relation relation(const Outer& outer, const Loop& inner, const IslandOptions& options) {
  const LoopPlane& plane = outer.loop.plane;
  if (!(plane.area > 0.0)) return Relation::None;
  if ((inner.hole->centroid - plane.centroid).norm() > (1.0 + options.reach) * plane.radius) {
    return Relation::None;
  }
  std::vector<Point2> outline;
  std::vector<double> heights;
  project(outer.loop, inner, outline, heights);
  if (!(signed_area(outline) < 0.0)) return Relation::None;
  const bool shares_vertex = shares_a_vertex(*outer.loop.hole, *inner.hole);
  if (!shares_vertex && inner.component == outer.loop.component) return Relation::None;
  const auto inside_count = std::count_if(outline.begin(), outline.end(),
                                          [&](const Point2& p) { return outer.grid.contains(p); });
  if (2 * static_cast<std::size_t>(inside_count) < outline.size()) return Relation::None;
  if (shares_vertex) return Relation::Touching;
  if (comes_within(inner.points, outer.loop.points, plane, outer.grid,
                   touching_tolerance(outer.loop))) {
    return Relation::Touching;
  }
  return lies_inside(outer, outline, heights, options) ? Relation::Island : Relation::None;
}

// Every other loop of the island's piece lies inside `outer` too: the whole piece floats in the
// hole (a sheet stacked under another is no island of its border).
bool whole_piece_inside(const Outer& outer, const std::vector<Loop>& loops, std::size_t island,
                        const IslandOptions& options) {
  for (std::size_t j = 0; j < loops.size(); ++j) {
    if (j == island || loops[j].component != loops[island].component) continue;
    std::vector<Point2> outline;
    std::vector<double> heights;
    project(outer.loop, loops[j], outline, heights);
    if (!lies_inside(outer, outline, heights, options)) return false;
  }
  return true;
}

// The loops' centroids in a k-d tree, so that each hole is compared with the loops near it
// rather than with every loop: relation() rules out at once every loop whose centroid lies beyond
// (1 + reach) times the hole's radius, and testing that for every pair took over a second
// for 20,000 holes (bench/NOTEBOOK.md). Loops without a finite centroid are not in the tree and
// are candidates for every hole.
class LoopsNear {
 public:
  LoopsNear(const std::vector<Loop>& loops, const IslandOptions& options)
      : loops_(loops), reach_(options.reach), tree_(3, cloud_) {
    for (std::size_t i = 0; i < loops.size(); ++i) {
      const Point& c = loops[i].hole->centroid;
      if (std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2])) {
        centroids_.push_back(c);
        loop_of_centroid_.push_back(static_cast<int>(i));
      } else {
        unplaced_.push_back(static_cast<int>(i));
      }
    }
    if (!centroids_.empty()) tree_.buildIndex();
  }

  // Ascending, every loop that relation(loops[outer], loop) does not rule out by distance (and a
  // few more); `outer` itself left out.
  std::vector<int> candidates(int outer) const {
    const Loop& o = loops_[static_cast<std::size_t>(outer)];
    const Point& c = o.plane.centroid;
    const double radius = (1.0 + reach_) * o.plane.radius;
    std::vector<int> found;
    if (!std::isfinite(radius) || !std::isfinite(c[0]) || !std::isfinite(c[1]) ||
        !std::isfinite(c[2])) {
      for (std::size_t i = 0; i < loops_.size(); ++i) found.push_back(static_cast<int>(i));
    } else {
      // Widened: the tree's squared distances round otherwise than relation()'s norm.
      const double search = radius * radius * (1.0 + 1e-9) + 1e-300;
      std::vector<std::pair<std::uint32_t, double>> within;
      if (!centroids_.empty()) {
        tree_.radiusSearch(c.data(), search, within, nanoflann::SearchParams(32, 0.0f, false));
      }
      for (const auto& [point, distance] : within) found.push_back(loop_of_centroid_[point]);
      found.insert(found.end(), unplaced_.begin(), unplaced_.end());
      std::sort(found.begin(), found.end());
    }
    found.erase(std::remove(found.begin(), found.end(), outer), found.end());
    return found;
  }

 private:
  const std::vector<Loop>& loops_;
  double reach_;
  std::vector<Point> centroids_;          // of the loops with finite ones
  std::vector<int> loop_of_centroid_;     // the loop of each of them
  detail::PointCloud cloud_{centroids_};  // the tree keeps a reference to it
  detail::PointCloudTree tree_;
  std::vector<int> unplaced_;  // the loops without a finite centroid
};

void add_note(IslandMap& map, int hole, const std::string& note) {
  if (map.note[hole].empty()) map.note[hole] = note;
}

std::string id_list(const std::vector<int>& ids) {
  std::string text;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == ids.size() ? " and " : ", ") + std::to_string(ids[i]);
  }
  return text;
}

// Gives island `island` to the innermost of `containers`, or records why it cannot be given.
void assign(IslandMap& map, const std::vector<Loop>& loops, int island,
            std::vector<int> containers) {
  std::sort(containers.begin(), containers.end(),
            [&](int a, int b) { return loops[a].plane.area < loops[b].plane.area; });
  const Loop& innermost = loops[containers[0]];
  const bool nested = std::all_of(containers.begin() + 1, containers.end(), [&](int other) {
    std::vector<Point2> outline;
    for (const auto& p : innermost.points) outline.push_back(loops[other].plane.project(p));
    return outline_inside(outline, OutlineGrid(loops[other].plane.outline));
  });
  if (nested) {
    map.outer[island] = containers[0];
    map.islands[containers[0]].push_back(island);
    return;
  }
  std::sort(containers.begin(), containers.end());
  const std::string note = "loop " + std::to_string(island) + " lies inside holes " +
                           id_list(containers) +
                           " (an island of two holes): each is filled without it, and it on its "
                           "own";
  add_note(map, island, note);
  for (const int outer : containers) add_note(map, outer, note);
}

}  // namespace

IslandMap find_islands(const Mesh& mesh, const std::vector<Hole>& holes,
                       const IslandOptions& options) {
  const bool search = options.detect && holes.size() >= 2;
  return find_islands(mesh, holes, options, search ? component_labels(mesh) : std::vector<int>{});
}

IslandMap find_islands(const Mesh& mesh, const std::vector<Hole>& holes,
                       const IslandOptions& options, const std::vector<int>& component) {
  IslandMap map;
  map.islands.resize(holes.size());
  map.outer.assign(holes.size(), -1);
  map.note.resize(holes.size());
  if (!options.detect || holes.size() < 2) return map;
  std::vector<Loop> loops;
  for (const auto& hole : holes) {
    Loop loop{&hole, loop_points(mesh, hole), {}, component[hole.vertices[0].idx()]};
    loop.plane = loop_plane(loop.points, hole.centroid);
    loops.push_back(std::move(loop));
  }
  std::vector<std::vector<int>> containers(holes.size());
  const LoopsNear near(loops, options);
  for (std::size_t o = 0; o < loops.size(); ++o) {
    if (!(loops[o].plane.area > 0.0)) continue;  // relation() is None for every loop
    const std::vector<int> candidates = near.candidates(static_cast<int>(o));
    if (candidates.empty()) continue;
    const Outer outer(loops[o]);
    for (const int candidate : candidates) {
      const auto i = static_cast<std::size_t>(candidate);
      const Relation r = relation(outer, loops[i], options);
      if (r == Relation::Island && whole_piece_inside(outer, loops, i, options)) {
        containers[i].push_back(static_cast<int>(o));
      }
      if (r == Relation::Touching) {
        const std::string note = "loop " + std::to_string(i) + " lies inside hole " +
                                 std::to_string(o) +
                                 " but touches its boundary (a patch between them would be "
                                 "pinched there): each is filled on its own";
        add_note(map, static_cast<int>(i), note);
        add_note(map, static_cast<int>(o), note);
      }
    }
  }
  for (std::size_t i = 0; i < holes.size(); ++i) {
    if (!containers[i].empty()) assign(map, loops, static_cast<int>(i), containers[i]);
  }
  // An island with islands of its own: its hole is filled without it, and it with its islands.
  for (std::size_t i = 0; i < holes.size(); ++i) {
    const int outer = map.outer[i];
    if (outer < 0 || !map.has_islands(static_cast<int>(i))) continue;
    std::erase(map.islands[outer], static_cast<int>(i));
    map.outer[i] = -1;
    const std::string note = "loop " + std::to_string(i) + " lies inside hole " +
                             std::to_string(outer) + " with islands of its own: hole " +
                             std::to_string(outer) + " is filled without it, and it with its own";
    add_note(map, static_cast<int>(i), note);
    add_note(map, outer, note);
  }
  return map;
}

}  // namespace holefill
