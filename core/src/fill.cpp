#include "holefill/fill.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <new>
#include <optional>
#include <thread>

namespace holefill {
namespace {

template <class Work>
double timed(Work&& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// ---- Triangle-triangle intersection
// --------------------------------------------------------------- Two triangles intersect when
// their interiors meet, or an edge of one passes through the interior of the other; touching along
// sides or at corners (a T-junction, a shared vertex) does not count.

// Relative tolerances: a point this close to a plane (times the triangles' size) lies in it; a
// point this close to a side (relative to the triangle's area) is on it, not inside.
constexpr double kPlaneTolerance = 1e-10;
constexpr double kInsideTolerance = 1e-9;

struct Triangle3 {
  std::array<Point, 3> corner;
  Point normal;  // unit
  double size;   // longest edge
};

// The two coordinates to keep when projecting onto the plane with this normal.
std::pair<int, int> projection_axes(const Point& normal) {
  const double x = std::abs(normal[0]), y = std::abs(normal[1]), z = std::abs(normal[2]);
  if (x >= y && x >= z) return {1, 2};
  if (y >= z) return {2, 0};
  return {0, 1};
}

struct Point2 {
  double x, y;
};

Point2 project(const Point& p, std::pair<int, int> axes) { return {p[axes.first], p[axes.second]}; }

double cross2(const Point2& o, const Point2& a, const Point2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

bool strictly_inside2(const Point2& p, const Point2& a, const Point2& b, const Point2& c) {
  const double area = cross2(a, b, c);
  if (area == 0.0) return false;
  const double sign = area > 0.0 ? 1.0 : -1.0, margin = kInsideTolerance * std::abs(area);
  return sign * cross2(a, b, p) > margin && sign * cross2(b, c, p) > margin &&
         sign * cross2(c, a, p) > margin;
}

// Segments [a, b] and [c, d] cross at a point inside both.
bool cross_properly2(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double margin =
      kInsideTolerance * std::hypot(b.x - a.x, b.y - a.y) * std::hypot(d.x - c.x, d.y - c.y);
  auto opposite = [margin](double u, double v) {
    return (u > margin && v < -margin) || (u < -margin && v > margin);
  };
  return opposite(cross2(c, d, a), cross2(c, d, b)) && opposite(cross2(a, b, c), cross2(a, b, d));
}

// The segment [s0, s1] passes through the triangle's interior.
bool segment_enters_triangle(const Point& s0, const Point& s1, const Triangle3& t) {
  const double d0 = OpenMesh::dot(t.normal, s0 - t.corner[0]);
  const double d1 = OpenMesh::dot(t.normal, s1 - t.corner[0]);
  const double tolerance = kPlaneTolerance * std::max(t.size, (s1 - s0).norm());
  if ((d0 > tolerance && d1 > tolerance) || (d0 < -tolerance && d1 < -tolerance)) return false;
  const auto axes = projection_axes(t.normal);
  const Point2 a = project(t.corner[0], axes), b = project(t.corner[1], axes),
               c = project(t.corner[2], axes);
  if (std::abs(d0) <= tolerance && std::abs(d1) <= tolerance) {
    const Point2 p = project(s0, axes), q = project(s1, axes);
    const Point2 middle{(p.x + q.x) / 2, (p.y + q.y) / 2};
    return strictly_inside2(p, a, b, c) || strictly_inside2(q, a, b, c) ||
           strictly_inside2(middle, a, b, c) || cross_properly2(p, q, a, b) ||
           cross_properly2(p, q, b, c) || cross_properly2(p, q, c, a);
  }
  const double along = std::clamp(d0 / (d0 - d1), 0.0, 1.0);
  return strictly_inside2(project(s0 + along * (s1 - s0), axes), a, b, c);
}

// Direction u lies strictly inside the wedge spanned by v1 and v2 (an angle below pi), all in
// the plane with this normal.
bool inside_wedge(const Point& u, const Point& v1, const Point& v2, const Point& normal) {
  auto sine = [&normal](const Point& x, const Point& y) {
    const double length = x.norm() * y.norm();
    return length > 0.0 ? OpenMesh::dot(OpenMesh::cross(x, y), normal) / length : 0.0;
  };
  const double turn = sine(v1, v2) > 0.0 ? 1.0 : -1.0;
  return turn * sine(v1, u) > kInsideTolerance && turn * sine(u, v2) > kInsideTolerance;
}

bool in_plane_of(const Triangle3& t, const Point& p, double size) {
  return std::abs(OpenMesh::dot(t.normal, p - t.corner[0])) <= kPlaneTolerance * size;
}

Point centre(const Triangle3& t) { return (t.corner[0] + t.corner[1] + t.corner[2]) / 3.0; }

// Two non-degenerate triangles intersect (corners at the same position count as shared).
bool triangles_intersect(const Triangle3& t1, const Triangle3& t2) {
  const double size = std::max(t1.size, t2.size);
  int shared_in_1[3], shared_in_2[3], shared = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (t1.corner[i] == t2.corner[j]) {
        shared_in_1[shared] = i;
        shared_in_2[shared++] = j;
        break;
      }
    }
  }
  if (shared >= 3) return true;  // the same triangle twice
  if (shared == 2) {
    // Meeting beyond the shared edge means folding onto each other in one plane.
    const Point& apex1 = t1.corner[3 - shared_in_1[0] - shared_in_1[1]];
    const Point& apex2 = t2.corner[3 - shared_in_2[0] - shared_in_2[1]];
    if (!in_plane_of(t1, apex2, size)) return false;
    const Point& p = t1.corner[shared_in_1[0]];
    const Point& q = t1.corner[shared_in_1[1]];
    return OpenMesh::dot(OpenMesh::cross(q - p, apex1 - p), OpenMesh::cross(q - p, apex2 - p)) >
           0.0;
  }
  if (shared == 1) {
    const int i = shared_in_1[0], j = shared_in_2[0];
    const Point& p = t1.corner[i];
    const Point &a = t1.corner[(i + 1) % 3], &b = t1.corner[(i + 2) % 3];
    const Point &c = t2.corner[(j + 1) % 3], &d = t2.corner[(j + 2) % 3];
    if (in_plane_of(t1, c, size) && in_plane_of(t1, d, size)) {
      // In one plane they overlap exactly when their wedges at p do.
      const Point& n = t1.normal;
      return inside_wedge(a - p, c - p, d - p, n) || inside_wedge(b - p, c - p, d - p, n) ||
             inside_wedge(c - p, a - p, b - p, n) || inside_wedge(d - p, a - p, b - p, n);
    }
    return segment_enters_triangle(a, b, t2) || segment_enters_triangle(c, d, t1) ||
           segment_enters_triangle(p, a, t2) || segment_enters_triangle(p, b, t2) ||
           segment_enters_triangle(p, c, t1) || segment_enters_triangle(p, d, t1);
  }
  for (int i = 0; i < 3; ++i) {
    if (segment_enters_triangle(t1.corner[i], t1.corner[(i + 1) % 3], t2) ||
        segment_enters_triangle(t2.corner[i], t2.corner[(i + 1) % 3], t1)) {
      return true;
    }
  }
  // In one plane, one may lie inside the other with no side crossing a side.
  if (in_plane_of(t1, t2.corner[0], size) && in_plane_of(t1, t2.corner[1], size) &&
      in_plane_of(t1, t2.corner[2], size)) {
    return segment_enters_triangle(centre(t1), centre(t1), t2) ||
           segment_enters_triangle(centre(t2), centre(t2), t1);
  }
  return false;
}

struct Box {
  Point low{INFINITY, INFINITY, INFINITY}, high{-INFINITY, -INFINITY, -INFINITY};
  void add(const Point& p) {
    low.minimize(p);
    high.maximize(p);
  }
  void grow(double margin) {
    low -= Point(margin, margin, margin);
    high += Point(margin, margin, margin);
  }
  bool overlaps(const Box& other) const {
    for (int axis = 0; axis < 3; ++axis) {
      if (high[axis] < other.low[axis] || other.high[axis] < low[axis]) return false;
    }
    return true;
  }
};

// A face as the intersection test needs it; nothing for a degenerate face.
std::optional<Triangle3> triangle_of(const Mesh& mesh, FaceHandle face) {
  Triangle3 t;
  int c = 0;
  for (const auto v : mesh.fv_range(face)) {
    if (c == 3) return std::nullopt;
    t.corner[c++] = mesh.point(v);
  }
  if (c != 3 || measure_triangle(t.corner[0], t.corner[1], t.corner[2], false).degenerate) {
    return std::nullopt;
  }
  t.normal = OpenMesh::cross(t.corner[1] - t.corner[0], t.corner[2] - t.corner[0]).normalized();
  t.size = std::max({(t.corner[1] - t.corner[0]).norm(), (t.corner[2] - t.corner[1]).norm(),
                     (t.corner[0] - t.corner[2]).norm()});
  return t;
}

// Boxes of a mesh's faces in a uniform grid, so that the faces near a patch are found without
// scanning the whole mesh for every stage of every hole.
class FaceIndex {
 public:
  explicit FaceIndex(const Mesh& mesh) {
    double extent = 0.0;
    std::size_t count = 0;
    std::vector<std::pair<int, Box>> boxes;
    for (const auto f : mesh.faces()) {
      const Box box = box_of(mesh, f);
      boxes.emplace_back(f.idx(), box);
      extent += (box.high - box.low).max();
      ++count;
    }
    cell_ = count && extent > 0.0 ? 2.0 * extent / static_cast<double>(count) : 1.0;
    for (const auto& [face, box] : boxes) {
      if (!place(face, box)) large_.emplace_back(face, box);
    }
    std::sort(cells_.begin(), cells_.end());
  }

  // A face added after the index was built (a finished patch's).
  void add(const Mesh& mesh, FaceHandle face) {
    added_.emplace_back(face.idx(), box_of(mesh, face));
  }

  // The faces whose boxes overlap `box`; nothing when that box covers too many cells to look
  // up one by one (then the caller scans the mesh).
  std::optional<std::vector<int>> near(const Box& box) const {
    std::array<std::int64_t, 3> low, high;
    const double cells = cell_range(box, low, high);
    if (!(cells <= kMaxCellsPerLookup)) return std::nullopt;
    std::vector<int> faces;
    for (auto x = low[0]; x <= high[0]; ++x) {
      for (auto y = low[1]; y <= high[1]; ++y) {
        for (auto z = low[2]; z <= high[2]; ++z) {
          const std::uint64_t key = key_of(x, y, z);
          auto at = std::lower_bound(cells_.begin(), cells_.end(),
                                     std::pair<std::uint64_t, int>(key, -1));
          for (; at != cells_.end() && at->first == key; ++at) faces.push_back(at->second);
        }
      }
    }
    for (const auto* list : {&large_, &added_}) {
      for (const auto& [face, face_box] : *list) {
        if (face_box.overlaps(box)) faces.push_back(face);
      }
    }
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    return faces;
  }

  static Box box_of(const Mesh& mesh, FaceHandle face) {
    Box box;
    for (const auto v : mesh.fv_range(face)) box.add(mesh.point(v));
    return box;
  }

 private:
  static constexpr double kMaxCellsPerFace = 64, kMaxCellsPerLookup = 1 << 20;

  std::int64_t cell_index(double x) const {
    return static_cast<std::int64_t>(std::floor(std::clamp(x / cell_, -1e15, 1e15)));
  }
  // The cells `box` touches, as index ranges per axis; returns how many (a double: it can be huge).
  double cell_range(const Box& box, std::array<std::int64_t, 3>& low,
                    std::array<std::int64_t, 3>& high) const {
    double cells = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
      low[axis] = cell_index(box.low[axis]);
      high[axis] = cell_index(box.high[axis]);
      cells *= static_cast<double>(high[axis] - low[axis] + 1);
    }
    return cells;
  }
  static std::uint64_t key_of(std::int64_t x, std::int64_t y, std::int64_t z) {
    // 21 bits per axis; distant cells may share a key, which only adds candidates.
    auto bits = [](std::int64_t i) { return static_cast<std::uint64_t>(i) & 0x1FFFFF; };
    return bits(x) << 42 | bits(y) << 21 | bits(z);
  }
  // Files the face under every cell its box touches; false when that is too many.
  bool place(int face, const Box& box) {
    std::array<std::int64_t, 3> low, high;
    const double cells = cell_range(box, low, high);
    if (!(cells <= kMaxCellsPerFace)) return false;
    for (auto x = low[0]; x <= high[0]; ++x) {
      for (auto y = low[1]; y <= high[1]; ++y) {
        for (auto z = low[2]; z <= high[2]; ++z) cells_.emplace_back(key_of(x, y, z), face);
      }
    }
    return true;
  }

  double cell_ = 1.0;
  std::vector<std::pair<std::uint64_t, int>> cells_;  // sorted by cell
  std::vector<std::pair<int, Box>> large_, added_;
};

// The pairs count_patch_intersections counts; `index` (when given) holds every face of the mesh
// but the patch's, so that only faces near the patch are looked at.
std::size_t count_intersections(const Mesh& mesh, const Patch& patch, const FaceIndex* index);

// ---- Undoing a stage
// --------------------------------------------------------------------------------

bool has_degenerate_face(const Mesh& mesh, const Patch& patch) {
  for (const auto f : patch.faces) {
    std::array<Point, 3> p;
    int c = 0;
    for (const auto v : mesh.fv_range(f)) p[c++ % 3] = mesh.point(v);
    if (measure_triangle(p[0], p[1], p[2], false).degenerate) return true;
  }
  return false;
}

// The patch's faces, new vertices and new edges are the newest elements of the mesh, so deleting
// them and collecting garbage moves no other element.
bool patch_is_newest(const Mesh& mesh, const Patch& patch) {
  const int first_face = static_cast<int>(mesh.n_faces() - patch.faces.size());
  const int first_vertex = static_cast<int>(mesh.n_vertices() - patch.new_vertices.size());
  for (const auto f : patch.faces) {
    if (f.idx() < first_face) return false;
  }
  for (const auto v : patch.new_vertices) {
    if (v.idx() < first_vertex) return false;
  }
  // The patch's own edges lie between two of its faces (its other edges are the hole's boundary).
  std::size_t interior_halfedges = 0;
  int oldest_interior_edge = static_cast<int>(mesh.n_edges());
  for (const auto f : patch.faces) {
    for (const auto h : mesh.fh_range(f)) {
      const FaceHandle other = mesh.opposite_face_handle(h);
      if (!other.is_valid() || other.idx() < first_face) continue;
      ++interior_halfedges;
      oldest_interior_edge = std::min(oldest_interior_edge, mesh.edge_handle(h).idx());
    }
  }
  return oldest_interior_edge >= static_cast<int>(mesh.n_edges() - interior_halfedges / 2);
}

// What a stage can be undone to: the patch's triangles and vertices as they are now, or, when
// the patch is not the newest part of the mesh (a viewer stepping holes in turn), the whole mesh.
class StageUndo {
 public:
  StageUndo(const Mesh& mesh, const Patch& patch) : patch_(patch) {
    if (!patch_is_newest(mesh, patch)) {
      whole_mesh_ = mesh;
      return;
    }
    for (const auto f : patch.faces) {
      std::array<VertexHandle, 3> corners;
      int c = 0;
      for (const auto v : mesh.fv_range(f)) corners[c++ % 3] = v;
      triangles_.push_back(corners);
      face_stages_.push_back(face_stage(mesh, f));
    }
    for (const auto v : patch.new_vertices) positions_.push_back(mesh.point(v));
  }

  // Puts the mesh and `patch` back as they were when this was made.
  void undo(Mesh& mesh, Patch& patch) const {
    if (whole_mesh_) {
      mesh = *whole_mesh_;
      patch = patch_;
      return;
    }
    for (const auto f : patch.faces) {
      if (!mesh.status(f).deleted()) mesh.delete_face(f, false);
    }
    for (const auto v : patch.new_vertices) {
      if (!mesh.status(v).deleted()) mesh.delete_vertex(v, false);
    }
    mesh.garbage_collection();
    // Added again in the same order, every element gets back its index.
    patch = patch_;
    patch.faces.clear();
    PatchTags tags(mesh);
    for (std::size_t i = 0; i < positions_.size(); ++i) {
      patch.new_vertices[i] = mesh.add_vertex(positions_[i]);
      mesh.property(tags.vertex_stage, patch.new_vertices[i]) =
          static_cast<std::uint8_t>(Stage::Refined);
    }
    for (std::size_t i = 0; i < triangles_.size(); ++i) {
      const FaceHandle f = mesh.add_face(triangles_[i][0], triangles_[i][1], triangles_[i][2]);
      mesh.property(tags.face_stage, f) = static_cast<std::uint8_t>(face_stages_[i]);
      patch.faces.push_back(f);
    }
  }

 private:
  Patch patch_;
  std::optional<Mesh> whole_mesh_;
  std::vector<std::array<VertexHandle, 3>> triangles_;
  std::vector<Stage> face_stages_;
  std::vector<Point> positions_;
};

// ---- The stages ---------------------------------------------------------------------------------

// The smoothing stage: the paper's umbrella operator, or fairing with umbrella as the fallback.
void smooth(Mesh& mesh, HoleFill& fill, const SmoothOptions& options) {
  if (options.method == SmoothMethod::Fair) {
    const FairResult result = fair_patch(mesh, fill.patch, options.fair);
    if (result.solved) {
      fill.patch.stage = Stage::Smoothed;
      return;
    }
    fill.smoothing_note = "fairing fell back to umbrella smoothing: " + result.problem;
  }
  smooth_patch(mesh, fill.patch, options);
}

// Why a finished stage must be undone: it made a degenerate triangle, or it made a patch that
// did not intersect the mesh intersect it. Empty when the stage may stay.
std::string stage_problem(const Mesh& mesh, const HoleFill& fill, const FaceIndex* index,
                          std::size_t& intersections) {
  if (has_degenerate_face(mesh, fill.patch)) return "it made a degenerate (zero-area) triangle";
  intersections = count_intersections(mesh, fill.patch, index);
  if (fill.self_intersections == 0 && intersections > 0) {
    return "it made the patch intersect the mesh";
  }
  return {};
}

// advance(), with the triangulation already planned when `plan` is given, and the faces outside
// the patch indexed when `index` is.
bool advance_with(Mesh& mesh, const Hole& hole, HoleFill& fill, const FillOptions& options,
                  const PlannedTriangulation* plan, const FaceIndex* index) {
  fill.hole_id = hole.id;
  fill.boundary_edges = hole.size();
  if (fill.failed()) return false;
  switch (fill.stage()) {
    case Stage::Original: {
      TriangulateHoleResult result;
      fill.times.triangulate_seconds += timed([&] {
        result = plan ? apply_triangulation(mesh, hole, *plan)
                      : triangulate_hole(mesh, hole, options.triangulate);
      });
      if (!result.patch) {
        fill.failure = result.failure;
        return false;
      }
      fill.patch = std::move(*result.patch);
      fill.times.check_seconds +=
          timed([&] { fill.self_intersections = count_intersections(mesh, fill.patch, index); });
      break;
    }
    case Stage::Triangulated: {
      const StageUndo undo(mesh, fill.patch);
      std::size_t intersections = 0;
      fill.times.refine_seconds = 0.0;
      auto refine_and_check = [&](const RefineOptions& refine) {
        std::string problem;
        fill.times.refine_seconds += timed([&] {
          try {
            fill.refinement = refine_patch(mesh, fill.patch, refine);
          } catch (const std::bad_alloc&) {
            problem = "not enough memory";
          }
        });
        if (problem.empty()) {
          fill.times.check_seconds +=
              timed([&] { problem = stage_problem(mesh, fill, index, intersections); });
        }
        return problem;
      };
      std::string problem = refine_and_check(options.refine);
      if (!problem.empty() && options.refine.remesh) {
        // The paper's refinement alone may be fine where the remeshing on top of it was not.
        undo.undo(mesh, fill.patch);
        RefineOptions without_remesh = options.refine;
        without_remesh.remesh = false;
        const std::string remesh_problem = problem;
        problem = refine_and_check(without_remesh);
        if (problem.empty()) fill.refinement_note = "remeshing undone: " + remesh_problem;
      }
      if (!problem.empty()) {
        undo.undo(mesh, fill.patch);
        fill.refinement = RefineResult{};
        fill.refinement_note = "refinement undone: " + problem;
      } else {
        fill.self_intersections = intersections;
      }
      fill.patch.stage = Stage::Refined;
      break;
    }
    case Stage::Refined: {
      std::vector<Point> positions;
      for (const auto v : fill.patch.new_vertices) positions.push_back(mesh.point(v));
      std::string problem;
      std::size_t intersections = 0;
      fill.times.smooth_seconds = timed([&] { smooth(mesh, fill, options.smooth); });
      fill.times.check_seconds +=
          timed([&] { problem = stage_problem(mesh, fill, index, intersections); });
      if (!problem.empty()) {
        for (std::size_t i = 0; i < positions.size(); ++i) {
          mesh.set_point(fill.patch.new_vertices[i], positions[i]);
        }
        fill.smoothing_note +=
            (fill.smoothing_note.empty() ? "" : "; ") + std::string("smoothing undone: ") + problem;
      } else {
        fill.self_intersections = intersections;
      }
      fill.patch.stage = Stage::Smoothed;
      break;
    }
    case Stage::Smoothed:
      return false;
  }
  fill.stats = patch_stats(mesh, fill.patch);
  return true;
}

HoleFill fill_planned(Mesh& mesh, const Hole& hole, const FillOptions& options,
                      const PlannedTriangulation* plan, const FaceIndex* index) {
  HoleFill fill;
  while (fill.stage() < options.last_stage &&
         advance_with(mesh, hole, fill, options, plan, index)) {
  }
  return fill;
}

}  // namespace

namespace {

std::size_t count_intersections(const Mesh& mesh, const Patch& patch, const FaceIndex* index) {
  if (patch.faces.empty()) return 0;
  std::vector<Triangle3> patch_triangles;
  std::vector<Box> patch_boxes;
  std::vector<int> patch_face_ids;
  Box reach;
  for (const auto f : patch.faces) {
    const auto t = triangle_of(mesh, f);
    if (!t) continue;
    Box box;
    for (const auto& p : t->corner) box.add(p);
    reach.add(box.low);
    reach.add(box.high);
    patch_triangles.push_back(*t);
    patch_boxes.push_back(box);
    patch_face_ids.push_back(f.idx());
  }
  if (patch_triangles.empty()) return 0;
  const double margin = 1e-9 * (reach.high - reach.low).norm();
  reach.grow(margin);
  std::vector<int> is_patch(mesh.n_faces(), -1);
  for (std::size_t i = 0; i < patch_face_ids.size(); ++i) is_patch[patch_face_ids[i]] = int(i);

  // The other faces near the patch, bucketed in a uniform grid over the patch's reach.
  struct Other {
    Triangle3 triangle;
    Box box;
    int patch_index;  // -1 for a face outside the patch
  };
  std::vector<Other> others;
  auto consider = [&](FaceHandle f) {
    const Box box = FaceIndex::box_of(mesh, f);
    if (!box.overlaps(reach)) return;
    if (const auto t = triangle_of(mesh, f)) others.push_back({*t, box, is_patch[f.idx()]});
  };
  const auto near = index ? index->near(reach) : std::nullopt;
  if (near) {
    for (const int f : *near) {
      if (is_patch[f] < 0) consider(FaceHandle(f));
    }
    for (const auto f : patch.faces) consider(f);
  } else {
    for (const auto f : mesh.faces()) consider(f);
  }
  const Point extent = reach.high - reach.low;
  const double cells_per_axis =
      std::clamp(std::cbrt(static_cast<double>(others.size())), 1.0, 64.0);
  const double cell = std::max({extent[0], extent[1], extent[2]}) / cells_per_axis;
  auto cell_range = [&](const Box& box, int axis) {
    auto index = [&](double x) {
      return cell > 0.0 ? static_cast<int>(
                              std::clamp((x - reach.low[axis]) / cell, 0.0, cells_per_axis - 1.0))
                        : 0;
    };
    return std::pair<int, int>(index(box.low[axis]), index(box.high[axis]));
  };
  const int n = static_cast<int>(cells_per_axis);
  std::vector<std::vector<int>> grid(static_cast<std::size_t>(n) * n * n);
  for (std::size_t o = 0; o < others.size(); ++o) {
    const auto [x0, x1] = cell_range(others[o].box, 0);
    const auto [y0, y1] = cell_range(others[o].box, 1);
    const auto [z0, z1] = cell_range(others[o].box, 2);
    for (int x = x0; x <= x1; ++x) {
      for (int y = y0; y <= y1; ++y) {
        for (int z = z0; z <= z1; ++z) grid[(x * n + y) * n + z].push_back(static_cast<int>(o));
      }
    }
  }

  std::size_t pairs = 0;
  std::vector<int> seen(others.size(), -1);
  for (std::size_t i = 0; i < patch_triangles.size(); ++i) {
    const auto [x0, x1] = cell_range(patch_boxes[i], 0);
    const auto [y0, y1] = cell_range(patch_boxes[i], 1);
    const auto [z0, z1] = cell_range(patch_boxes[i], 2);
    for (int x = x0; x <= x1; ++x) {
      for (int y = y0; y <= y1; ++y) {
        for (int z = z0; z <= z1; ++z) {
          for (const int o : grid[(x * n + y) * n + z]) {
            if (seen[o] == static_cast<int>(i)) continue;
            seen[o] = static_cast<int>(i);
            const Other& other = others[o];
            // Pairs within the patch are counted once, from their first triangle.
            if (other.patch_index >= 0 && other.patch_index <= static_cast<int>(i)) continue;
            if (!other.box.overlaps(patch_boxes[i])) continue;
            if (triangles_intersect(patch_triangles[i], other.triangle)) ++pairs;
          }
        }
      }
    }
  }
  return pairs;
}

}  // namespace

std::size_t count_patch_intersections(const Mesh& mesh, const Patch& patch) {
  return count_intersections(mesh, patch, nullptr);
}

bool advance(Mesh& mesh, const Hole& hole, HoleFill& fill, const FillOptions& options) {
  return advance_with(mesh, hole, fill, options, nullptr, nullptr);
}

HoleFill fill_hole(Mesh& mesh, const Hole& hole, const FillOptions& options) {
  return fill_planned(mesh, hole, options, nullptr, nullptr);
}

bool HoleSelection::includes(const Hole& hole) const {
  if (max_boundary_edges && hole.size() > max_boundary_edges) return false;
  return hole_ids.empty() || std::find(hole_ids.begin(), hole_ids.end(), hole.id) != hole_ids.end();
}

std::vector<HoleFill> fill_holes(Mesh& mesh, const std::vector<Hole>& holes,
                                 const FillOptions& options, const HoleSelection& selection) {
  std::vector<const Hole*> chosen;
  for (const auto& hole : holes) {
    if (selection.includes(hole)) chosen.push_back(&hole);
  }
  // The dynamic programs only read the mesh and dominate the time: run them on every core,
  // largest holes first (holes come sorted by size), then add the patches one by one.
  std::vector<PlannedTriangulation> plans(chosen.size());
  std::vector<double> plan_seconds(chosen.size(), 0.0);
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < chosen.size(); i = next++) {
      plan_seconds[i] =
          timed([&] { plans[i] = plan_triangulation(mesh, *chosen[i], options.triangulate); });
    }
  };
  const unsigned threads =
      std::min<unsigned>(std::max(1u, std::thread::hardware_concurrency()), chosen.size());
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& thread : pool) thread.join();

  // Patches are checked against the faces near them; each finished patch joins those faces.
  FaceIndex index(mesh);
  std::vector<HoleFill> fills;
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    fills.push_back(fill_planned(mesh, *chosen[i], options, &plans[i], &index));
    fills.back().times.triangulate_seconds += plan_seconds[i];
    for (const auto f : fills.back().patch.faces) index.add(mesh, f);
  }
  return fills;
}

}  // namespace holefill
