#include "holefill/patch.h"

#include <cmath>

#include "geometry.h"
#include "property_handles.h"

namespace holefill {
namespace {
constexpr const char* kFaceStage = "holefill:face_stage";
constexpr const char* kVertexStage = "holefill:vertex_stage";
constexpr const char* kScale = "holefill:scale";

// Whether the angles at c and d opposite edge a-b clearly sum to at most pi, without atan2: for
// angles in (0, pi), alpha + beta <= pi exactly when cot(alpha) + cot(beta) >= 0. The margin
// leaves every case that rounding could decide either way to the exact test.
bool clearly_delaunay(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Point ca = a - c, cb = b - c, da = a - d, db = b - d;
  const double sin_c = OpenMesh::cross(ca, cb).norm(), sin_d = OpenMesh::cross(da, db).norm();
  if (!(sin_c > 0.0 && sin_d > 0.0)) return false;
  const double cot_c = OpenMesh::dot(ca, cb) / sin_c, cot_d = OpenMesh::dot(da, db) / sin_d;
  return cot_c + cot_d > 1e-6 * (std::abs(cot_c) + std::abs(cot_d) + 1.0);
}
}  // namespace

const char* to_string(Stage stage) {
  switch (stage) {
    case Stage::Original:
      return "open";
    case Stage::Triangulated:
      return "triangulated";
    case Stage::Refined:
      return "refined";
    case Stage::Smoothed:
      return "smoothed";
  }
  return "?";
}

PatchTags::PatchTags(Mesh& mesh) {
  detail::find_or_add_property(mesh, face_stage, kFaceStage);
  detail::find_or_add_property(mesh, vertex_stage, kVertexStage);
  detail::find_or_add_property(mesh, scale, kScale);
}

Stage face_stage(const Mesh& mesh, FaceHandle face) {
  OpenMesh::FPropHandleT<std::uint8_t> handle;
  if (!mesh.get_property_handle(handle, kFaceStage)) return Stage::Original;
  return static_cast<Stage>(mesh.property(handle, face));
}

bool should_swap_edge(const Mesh& mesh, EdgeHandle edge) {
  const auto h0 = mesh.halfedge_handle(edge, 0), h1 = mesh.halfedge_handle(edge, 1);
  if (mesh.is_boundary(h0) || mesh.is_boundary(h1)) return false;
  const Point& a = mesh.point(mesh.from_vertex_handle(h0));
  const Point& b = mesh.point(mesh.to_vertex_handle(h0));
  const Point& c = mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h0)));
  const Point& d = mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h1)));
  if (clearly_delaunay(a, b, c, d)) return false;  // most edges: no atan2 needed
  const double opposite_now = geometry::angle_at(c, a, b) + geometry::angle_at(d, a, b);
  const double opposite_swapped = geometry::angle_at(a, c, d) + geometry::angle_at(b, c, d);
  // On a curved patch both diagonals of a quad can see more than pi; swapping only when it lowers
  // the opposite-angle sum keeps relaxation from swapping an edge back and forth. The margin
  // keeps co-circular configurations still.
  constexpr double kMargin = 1e-9;
  return opposite_now > M_PI + kMargin && opposite_swapped < opposite_now - kMargin;
}

}  // namespace holefill
