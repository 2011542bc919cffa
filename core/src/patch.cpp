#include "holefill/patch.h"

#include <cmath>

namespace holefill {
namespace {
constexpr const char* kFaceStage = "holefill:face_stage";
constexpr const char* kVertexStage = "holefill:vertex_stage";
constexpr const char* kScale = "holefill:scale";

template <class Handle>
void find_or_add(Mesh& mesh, Handle& handle, const char* name) {
  if (!mesh.get_property_handle(handle, name)) mesh.add_property(handle, name);
}

double angle_at(const Point& corner, const Point& a, const Point& b) {
  const Point u = a - corner, v = b - corner;
  return std::atan2(OpenMesh::cross(u, v).norm(), OpenMesh::dot(u, v));
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
  find_or_add(mesh, face_stage, kFaceStage);
  find_or_add(mesh, vertex_stage, kVertexStage);
  find_or_add(mesh, scale, kScale);
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
  const double opposite_now = angle_at(c, a, b) + angle_at(d, a, b);
  const double opposite_swapped = angle_at(a, c, d) + angle_at(b, c, d);
  // On a curved patch both diagonals of a quad can see more than pi; swapping only when it lowers
  // the opposite-angle sum keeps relaxation from swapping an edge back and forth. The margin
  // keeps co-circular configurations still.
  constexpr double kMargin = 1e-9;
  return opposite_now > M_PI + kMargin && opposite_swapped < opposite_now - kMargin;
}

}  // namespace holefill
