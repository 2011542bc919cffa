#include "holefill/bridge.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <new>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "dp_step.h"
#include "geometry.h"
#include "hole_triangulation.h"
#include "loop_tree.h"

namespace holefill {
namespace {

using Bridges = std::vector<std::pair<VertexHandle, VertexHandle>>;

// The polygon the dynamic program sees: hole_polygon's, plus the chords that would repeat a bridge
// (between the other copies of its two endpoints).
HolePolygon joined_hole_polygon(const Mesh& mesh, const Hole& joined, const Bridges& bridges) {
  HolePolygon polygon = detail::hole_polygon(mesh, joined);
  const int n = static_cast<int>(joined.vertices.size());
  std::unordered_map<int, std::vector<int>> positions;
  for (int i = 0; i < n; ++i) positions[joined.vertices[i].idx()].push_back(i);
  for (const auto& [a, b] : bridges) {
    for (const int i : positions[a.idx()]) {
      for (const int k : positions[b.idx()]) {
        const int low = std::min(i, k), high = std::max(i, k);
        if (high - low != 1 && high - low != n - 1)
          polygon.forbidden_chords.emplace_back(low, high);
      }
    }
  }
  return polygon;
}

// The largest dihedral angle across the bridges, which the dynamic program cannot see (a bridge is
// a polygon edge with nothing known across it, twice).
double bridge_dihedral(const HolePolygon& polygon, const Hole& joined,
                       const std::vector<std::array<int, 3>>& triangles, const Bridges& bridges) {
  std::map<std::pair<int, int>, Point> normal_of_directed_edge;
  for (const auto& t : triangles) {
    const Point normal =
        detail::unit_normal(polygon.points[t[0]], polygon.points[t[1]], polygon.points[t[2]]);
    for (int e = 0; e < 3; ++e) {
      normal_of_directed_edge[{joined.vertices[t[e]].idx(),
                               joined.vertices[t[(e + 1) % 3]].idx()}] = normal;
    }
  }
  double largest = 0.0;
  for (const auto& [a, b] : bridges) {
    const auto one = normal_of_directed_edge.find({a.idx(), b.idx()});
    const auto other = normal_of_directed_edge.find({b.idx(), a.idx()});
    if (one != normal_of_directed_edge.end() && other != normal_of_directed_edge.end()) {
      largest = std::max(largest, geometry::angle_between_normals(one->second, other->second));
    }
  }
  return largest;
}

// A joined polygon with its triangulation and what the weight makes of it.
struct Candidate {
  Hole joined;
  Bridges bridges;
  std::optional<PolygonTriangulation> triangulation;
  WeightValue value;
};

// The chords of a triangulation of the joined polygon that join the same two vertices as another
// of its chords or edges (from two copies of a bridge's end to one vertex), as (i, k), i < k.
std::vector<std::pair<int, int>> repeated_chords(const Hole& joined,
                                                 const std::vector<std::array<int, 3>>& triangles) {
  const int n = static_cast<int>(joined.vertices.size());
  std::unordered_map<std::uint64_t, std::vector<std::pair<int, int>>> sides_of_pair;
  for (const auto& t : triangles) {
    for (int e = 0; e < 3; ++e) {
      const int low = std::min(t[e], t[(e + 1) % 3]), high = std::max(t[e], t[(e + 1) % 3]);
      const auto u = static_cast<std::uint32_t>(joined.vertices[low].idx());
      const auto v = static_cast<std::uint32_t>(joined.vertices[high].idx());
      auto& sides = sides_of_pair[std::uint64_t{std::min(u, v)} << 32 | std::max(u, v)];
      if (std::find(sides.begin(), sides.end(), std::pair(low, high)) == sides.end()) {
        sides.emplace_back(low, high);
      }
    }
  }
  std::vector<std::pair<int, int>> repeated;
  for (const auto& [pair, sides] : sides_of_pair) {
    if (sides.size() < 2) continue;
    for (const auto& [low, high] : sides) {
      if (high - low != 1 && high - low != n - 1) repeated.emplace_back(low, high);
    }
  }
  std::sort(repeated.begin(), repeated.end());
  return repeated;
}

// Triangulations of a tree's polygon made again at most this many times, each with the chords
// that repeated an edge forbidden.
constexpr int kTreeRepairs = 8;

// The joined polygon's triangulation and what the weight makes of it. A triangulation that uses
// an edge twice is no patch. For a polygon joined along a tree (`along_tree`), which has only
// this one chance, chords that leave a bridge end's corner are forbidden first, and a
// triangulation that still repeats an edge is made again without the repeated chords,
// kTreeRepairs times at most; otherwise the candidate has none.
Candidate triangulate_candidate(const Mesh& mesh, Hole joined, Bridges bridges,
                                const TriangulateOptions& options, bool along_tree = false) {
  Candidate candidate{std::move(joined), std::move(bridges), std::nullopt, {}};
  HolePolygon polygon = joined_hole_polygon(mesh, candidate.joined, candidate.bridges);
  const int repairs = along_tree ? kTreeRepairs : 0;
  if (along_tree) {
    const auto outside = detail::chords_outside_corners(candidate.joined, polygon.points,
                                                        2 * options.restricted.nearest_neighbours,
                                                        options.restricted.pocket_edges);
    polygon.forbidden_chords.insert(polygon.forbidden_chords.end(), outside.begin(), outside.end());
  }
  std::optional<PolygonTriangulation> triangulation;
  for (int round = 0; round <= repairs; ++round) {
    triangulation = triangulate_polygon(polygon, options);
    if (!triangulation) return candidate;
    const auto repeated = repeated_chords(candidate.joined, triangulation->triangles);
    if (repeated.empty()) break;
    polygon.forbidden_chords.insert(polygon.forbidden_chords.end(), repeated.begin(),
                                    repeated.end());
    triangulation.reset();
  }
  if (!triangulation || !is_manifold_triangulation(candidate.joined, triangulation->triangles)) {
    return candidate;
  }
  TriangulationQuality quality = evaluate_triangulation(polygon, triangulation->triangles);
  quality.max_dihedral = std::max(
      quality.max_dihedral,
      bridge_dihedral(polygon, candidate.joined, triangulation->triangles, candidate.bridges));
  candidate.value = weight_value(quality, options);
  candidate.triangulation = std::move(triangulation);
  return candidate;
}

double squared_distance(const Mesh& mesh, VertexHandle a, VertexHandle b) {
  return (mesh.point(a) - mesh.point(b)).sqrnorm();
}

// The shortest bridges from `loop` to `polygon`: from each loop vertex to its nearest polygon
// vertex, shortest first, leaving out pairs an existing mesh edge already joins.
std::vector<std::pair<int, int>> candidate_bridges(const Mesh& mesh, const Hole& polygon,
                                                   const Hole& loop, int count) {
  std::vector<std::pair<double, std::pair<int, int>>> nearest;
  for (int j = 0; j < static_cast<int>(loop.vertices.size()); ++j) {
    double best = std::numeric_limits<double>::infinity();
    int best_i = -1;
    for (int i = 0; i < static_cast<int>(polygon.vertices.size()); ++i) {
      const double d = squared_distance(mesh, polygon.vertices[i], loop.vertices[j]);
      if (d < best && !mesh.find_halfedge(polygon.vertices[i], loop.vertices[j]).is_valid()) {
        best = d;
        best_i = i;
      }
    }
    if (best_i >= 0) nearest.push_back({best, {best_i, j}});
  }
  std::sort(nearest.begin(), nearest.end());
  std::vector<std::pair<int, int>> chosen;
  for (std::size_t c = 0; c < nearest.size() && static_cast<int>(chosen.size()) < count; ++c) {
    chosen.push_back(nearest[c].second);
  }
  return chosen;
}

double loop_distance(const Mesh& mesh, const Hole& a, const Hole& b) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto u : a.vertices) {
    for (const auto v : b.vertices) best = std::min(best, squared_distance(mesh, u, v));
  }
  return best;
}

// Why these loops cannot be joined (a loop through a vertex twice, two loops through one vertex),
// or empty.
Failure loops_problem(const std::vector<const Hole*>& loops) {
  if (loops.size() < 2) return {FailureKind::NoBridge, "joining needs at least two boundary loops"};
  if (loops.size() > kMostJoinedLoops) {
    return {
        FailureKind::TooManyLoops,
        "it holds " + std::to_string(loops.size() - 1) +
            " other loops (islands, a bridged hole), more than the " +
            std::to_string(kMostJoinedLoops - 1) +
            " one patch joins (kMostJoinedLoops in bridge.h); --islands off fills each loop on its "
            "own"};
  }
  std::unordered_map<int, int> loop_of_vertex;
  for (const Hole* loop : loops) {
    for (const auto v : loop->vertices) {
      const auto [at, inserted] = loop_of_vertex.emplace(v.idx(), loop->id);
      if (inserted) continue;
      return {FailureKind::LoopsShareVertex,
              at->second == loop->id
                  ? "hole " + std::to_string(loop->id) + " passes twice through vertex " +
                        std::to_string(v.idx() + 1) + " (a pinched loop)"
                  : "holes " + std::to_string(at->second) + " and " + std::to_string(loop->id) +
                        " touch at vertex " + std::to_string(v.idx() + 1) +
                        "; a patch joining them would leave a non-manifold vertex"};
    }
  }
  std::size_t total = 0;
  for (const Hole* loop : loops) total += loop->size() + 2;
  if (total >= kMaxPolygonSize) {
    return {FailureKind::TooManyEdges, "the joined polygon would have " + std::to_string(total) +
                                           " edges, more than the dynamic program takes"};
  }
  return {};
}

}  // namespace

Hole splice_loop(const Hole& polygon, const Hole& loop, int at_polygon, int at_loop) {
  Hole joined;
  joined.id = polygon.id;
  joined.perimeter = polygon.perimeter + loop.perimeter;
  const std::size_t n = polygon.size(), m = loop.size();
  joined.centroid =
      (polygon.centroid * static_cast<double>(n) + loop.centroid * static_cast<double>(m)) /
      static_cast<double>(n + m);
  joined.mean_surrounding_edge_length =
      (polygon.mean_surrounding_edge_length * static_cast<double>(n) +
       loop.mean_surrounding_edge_length * static_cast<double>(m)) /
      static_cast<double>(n + m);
  auto add = [&joined](VertexHandle v, HalfedgeHandle h) {
    joined.vertices.push_back(v);
    joined.halfedges.push_back(h);
  };
  for (int i = 0; i < at_polygon; ++i) add(polygon.vertices[i], polygon.halfedges[i]);
  add(polygon.vertices[at_polygon], HalfedgeHandle());
  for (std::size_t j = 0; j < m; ++j) {
    const std::size_t at = (static_cast<std::size_t>(at_loop) + j) % m;
    add(loop.vertices[at], loop.halfedges[at]);
  }
  add(loop.vertices[at_loop], HalfedgeHandle());
  for (std::size_t i = static_cast<std::size_t>(at_polygon); i < n; ++i) {
    add(polygon.vertices[i], polygon.halfedges[i]);
  }
  return joined;
}

bool is_manifold_triangulation(const Hole& polygon,
                               const std::vector<std::array<int, 3>>& triangles) {
  std::unordered_set<std::uint64_t> directed;
  for (const auto& t : triangles) {
    for (int e = 0; e < 3; ++e) {
      const auto from = static_cast<std::uint32_t>(polygon.vertices[t[e]].idx());
      const auto to = static_cast<std::uint32_t>(polygon.vertices[t[(e + 1) % 3]].idx());
      if (from == to || !directed.insert(std::uint64_t{from} << 32 | to).second) return false;
    }
  }
  return true;
}

namespace {

// Whether plan_joined_loops weighs candidate bridges (JoinOptions::weighed_loops).
bool weighs_bridges(const std::vector<const Hole*>& loops, const TriangulateOptions& options,
                    const JoinOptions& join) {
  std::size_t edges = 0;
  for (const Hole* loop : loops) edges += loop->size() + 2;
  return loops.size() <= static_cast<std::size_t>(std::max(join.weighed_loops, 0)) + 1 &&
         edges <= options.restricted.above_edges;
}

// Joins the loops one by one, each by the best of its candidate bridges; false (and the failure
// in result.plan) when a loop has none that triangulates.
bool join_weighing_bridges(const Mesh& mesh, const std::vector<const Hole*>& loops,
                           const TriangulateOptions& options, const JoinOptions& join,
                           JoinedLoops& result) {
  std::vector<const Hole*> waiting(loops.begin() + 1, loops.end());
  while (!waiting.empty()) {
    auto nearest = std::min_element(waiting.begin(), waiting.end(), [&](auto* a, auto* b) {
      return loop_distance(mesh, result.polygon, *a) < loop_distance(mesh, result.polygon, *b);
    });
    const Hole& loop = **nearest;
    std::optional<Candidate> best;
    for (const auto& [i, j] :
         candidate_bridges(mesh, result.polygon, loop, join.candidate_bridges)) {
      Bridges bridges = result.bridges;
      bridges.emplace_back(result.polygon.vertices[i], loop.vertices[j]);
      Candidate candidate = triangulate_candidate(mesh, splice_loop(result.polygon, loop, i, j),
                                                  std::move(bridges), options);
      if (candidate.triangulation && (!best || candidate.value < best->value)) {
        best = std::move(candidate);
      }
    }
    if (!best) {
      result.plan.failure = {FailureKind::NoBridge,
                             "no bridge from hole " + std::to_string(loop.id) + " to hole " +
                                 std::to_string(result.polygon.id) +
                                 " gives a valid triangulation of the region between them"};
      return false;
    }
    result.polygon = std::move(best->joined);
    result.bridges = std::move(best->bridges);
    result.plan.triangulation = std::move(best->triangulation);
    waiting.erase(nearest);
  }
  return true;
}

// Joins the loops along a tree of shortest bridges (loop_tree.h) and triangulates once.
bool join_along_shortest_bridges(const Mesh& mesh, const std::vector<const Hole*>& loops,
                                 const TriangulateOptions& options, JoinedLoops& result) {
  detail::LoopTree tree = detail::join_along_tree(mesh, loops);
  Candidate joined =
      triangulate_candidate(mesh, std::move(tree.polygon), std::move(tree.bridges), options, true);
  result.polygon = std::move(joined.joined);
  result.bridges = std::move(joined.bridges);
  if (!joined.triangulation) {
    result.plan.failure = {FailureKind::NoTriangulation,
                           "the " + std::to_string(loops.size()) + " loops joined to hole " +
                               std::to_string(result.polygon.id) +
                               " by their shortest bridges have no valid triangulation"};
    return false;
  }
  result.plan.triangulation = std::move(joined.triangulation);
  return true;
}

}  // namespace

JoinedLoops plan_joined_loops(const Mesh& mesh, const std::vector<const Hole*>& loops,
                              const TriangulateOptions& options, const JoinOptions& join) {
  JoinedLoops result;
  if (!loops.empty()) result.polygon = *loops[0];
  if (Failure problem = loops_problem(loops); problem.failed()) {
    result.plan.failure = std::move(problem);
    return result;
  }
  try {
    const bool joined = weighs_bridges(loops, options, join)
                            ? join_weighing_bridges(mesh, loops, options, join, result)
                            : join_along_shortest_bridges(mesh, loops, options, result);
    if (!joined) return result;
  } catch (const std::bad_alloc&) {
    result.plan.triangulation.reset();
    result.plan.failure = {FailureKind::OutOfMemory,
                           "not enough memory to triangulate the joined loops"};
    return result;
  }
  if (result.plan.triangulation->quality.degenerate > 0) {
    result.plan.triangulation.reset();
    result.plan.failure = {
        FailureKind::DegenerateTriangle,
        "the triangulation of the joined loops would have a degenerate (zero-area) triangle"};
  }
  return result;
}

}  // namespace holefill
