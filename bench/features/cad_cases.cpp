#include "cad_cases.h"

#include <cmath>
#include <numbers>
#include <queue>
#include <random>
#include <utility>

#include "cad_shapes.h"

namespace holefill::features {
namespace {

constexpr int kRealSeedAttempts = 60;
constexpr int kMostFlipRounds = 50;
const double kFlatCosine = std::cos(1e-4);  // faces within 1e-4 radians: one plane (STL floats)

double dihedral_degrees(const Mesh& mesh, EdgeHandle e) {
  const auto h = mesh.halfedge_handle(e, 0);
  const FaceHandle f0 = mesh.face_handle(h), f1 = mesh.opposite_face_handle(h);
  if (!f0.is_valid() || !f1.is_valid()) return 0.0;
  const Point n0 = mesh.calc_face_normal(f0), n1 = mesh.calc_face_normal(f1);
  return std::atan2(OpenMesh::cross(n0, n1).norm(), OpenMesh::dot(n0, n1)) * 180.0 /
         std::numbers::pi;
}

// A vertex of `candidates` (drawn by `rng`) where a ball of `radius` cuts a clean disk.
std::optional<VertexHandle> clean_seed(const Mesh& closed,
                                       const std::vector<VertexHandle>& candidates, double radius,
                                       std::mt19937& rng) {
  if (candidates.empty()) return std::nullopt;
  for (int attempt = 0; attempt < kRealSeedAttempts; ++attempt) {
    const VertexHandle v = candidates[rng() % candidates.size()];
    if (cut_case({"", "", closed, closed.point(v), radius})) return v;
  }
  return std::nullopt;
}

}  // namespace

std::vector<CadCase> generated_cases() {
  std::vector<CadCase> cases;
  const Mesh box = make_box(1.0, 16);
  cases.push_back({"box-face", "box, hole inside a face (control: no crease)", box,
                   Point(0.05, 0.05, 1.0), 0.45});
  cases.push_back(
      {"box-edge", "box, hole across an edge (90° crease)", box, Point(1.0, 0.05, 1.0), 0.45});
  cases.push_back({"box-corner", "box, hole across a corner (three 90° creases)", box,
                   Point(1.0, 1.0, 1.0), 0.5});
  const Mesh cylinder = make_cylinder(1.0, 1.0, 64);
  const double a = 0.3;
  cases.push_back({"cylinder-side", "cylinder, hole in the side (control: no crease)", cylinder,
                   Point(std::cos(a), std::sin(a), 0.0), 0.4});
  cases.push_back({"cylinder-rim", "cylinder, hole across the rim of a flat cap (90° circle)",
                   cylinder, Point(std::cos(a), std::sin(a), 1.0), 0.4});
  const double inner = 0.7, fillet = 0.3;
  const Mesh rounded = make_rounded_box(inner, fillet, 12, 4);
  cases.push_back({"fillet-edge", "rounded box, hole across a filleted edge (no crease)", rounded,
                   Point(inner, 0.05, inner) + Point(1.0, 0.0, 1.0).normalized() * fillet, 0.45});
  cases.push_back({"fillet-corner", "rounded box, hole across a rounded corner (no crease)",
                   rounded, Point(inner, inner, inner) + Point(1.0, 1.0, 1.0).normalized() * fillet,
                   0.5});
  const Mesh step = make_step_block(8);
  cases.push_back({"step-concave", "L block, hole across the concave crease (270°)", step,
                   Point(1.0, 0.5, 1.0), 0.3});
  cases.push_back({"step-concave-wide",
                   "L block, hole along the concave crease, its rim across the two convex creases "
                   "next to the mixed corner",
                   step, Point(1.0, 0.55, 1.0), 0.4});
  cases.push_back(
      {"step-corner", "L block, hole across a convex corner", step, Point(2.0, 1.0, 1.0), 0.4});
  cases.push_back({"step-mixed", "L block, concave crease meeting a face (mixed corner)", step,
                   Point(1.0, 1.0, 1.0), 0.4});
  return cases;
}

std::vector<CadCase> real_cases(const std::string& name, const Mesh& closed, double sharp_degrees,
                                double radius_edges, unsigned seed) {
  std::vector<int> sharp_edges(closed.n_vertices(), 0);
  for (const auto e : closed.edges()) {
    if (dihedral_degrees(closed, e) <= sharp_degrees) continue;
    const auto h = closed.halfedge_handle(e, 0);
    ++sharp_edges[closed.from_vertex_handle(h).idx()];
    ++sharp_edges[closed.to_vertex_handle(h).idx()];
  }
  std::vector<VertexHandle> on_crease, at_corner;
  for (const auto v : closed.vertices()) {
    if (sharp_edges[v.idx()] == 2) on_crease.push_back(v);
    if (sharp_edges[v.idx()] >= 3) at_corner.push_back(v);
  }
  const double radius = radius_edges * quality::mean_edge_length(closed);
  std::mt19937 rng(seed);
  std::vector<CadCase> cases;
  if (const auto v = clean_seed(closed, on_crease, radius, rng)) {
    cases.push_back(
        {name + "-crease", name + ", hole across a crease", closed, closed.point(*v), radius});
  }
  if (const auto v = clean_seed(closed, at_corner, radius, rng)) {
    cases.push_back(
        {name + "-corner", name + ", hole across a corner", closed, closed.point(*v), radius});
  }
  return cases;
}

void split_long_edges(Mesh& mesh, double longest) {
  using Entry = std::pair<double, int>;  // length, edge index: the longest on top
  std::priority_queue<Entry> queue;
  for (const auto e : mesh.edges()) {
    const double length = mesh.calc_edge_length(e);
    if (length > longest) queue.emplace(length, e.idx());
  }
  while (!queue.empty()) {
    const auto [length, index] = queue.top();
    queue.pop();
    const EdgeHandle e(index);
    // An edge split since it was queued was queued again with its new length.
    if (mesh.calc_edge_length(e) != length) continue;
    const auto h = mesh.halfedge_handle(e, 0);
    const Point middle =
        (mesh.point(mesh.from_vertex_handle(h)) + mesh.point(mesh.to_vertex_handle(h))) * 0.5;
    const VertexHandle v = mesh.split(e, middle);
    for (const auto out : mesh.voh_range(v)) {
      const EdgeHandle around = mesh.edge_handle(out);
      const double around_length = mesh.calc_edge_length(around);
      if (around_length > longest) queue.emplace(around_length, around.idx());
    }
  }
}

void flip_flat_edges_to_delaunay(Mesh& mesh) {
  auto opposite_angle = [&](HalfedgeHandle h) {
    const Point a = mesh.point(mesh.from_vertex_handle(h)),
                b = mesh.point(mesh.to_vertex_handle(h));
    const Point c = mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h)));
    return std::atan2(OpenMesh::cross(a - c, b - c).norm(), OpenMesh::dot(a - c, b - c));
  };
  for (int round = 0; round < kMostFlipRounds; ++round) {
    std::size_t flips = 0;
    for (const auto e : mesh.edges()) {
      if (mesh.is_boundary(e) || !mesh.is_flip_ok(e)) continue;
      const auto h = mesh.halfedge_handle(e, 0), g = mesh.halfedge_handle(e, 1);
      // Only where the two faces lie in one plane, so that the surface stays the same; and only
      // if the new faces would lie in it too (the quadrilateral is convex: no fold).
      const Point n0 = mesh.calc_face_normal(mesh.face_handle(h));
      const Point n1 = mesh.calc_face_normal(mesh.face_handle(g));
      if (OpenMesh::dot(n0, n1) < kFlatCosine) continue;
      if (opposite_angle(h) + opposite_angle(g) <= std::numbers::pi + 1e-12) continue;
      const Point c = mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h)));
      const Point d = mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(g)));
      const Point a = mesh.point(mesh.from_vertex_handle(h)),
                  b = mesh.point(mesh.to_vertex_handle(h));
      // The new faces (c, a, d) and (d, b, c) face the same way as the old.
      if (OpenMesh::dot(OpenMesh::cross(a - c, d - c), n0) <= 0.0 ||
          OpenMesh::dot(OpenMesh::cross(d - c, b - c), n0) <= 0.0) {
        continue;
      }
      mesh.flip(e);
      ++flips;
    }
    if (flips == 0) return;
  }
}

std::optional<quality::CutMesh> cut_case(const CadCase& c, std::string* problem) {
  return quality::cut_ball(c.closed, c.center, c.radius, problem);
}

}  // namespace holefill::features
