#include "vertex_merge.h"

#include <algorithm>
#include <array>

#include "deletion_flags.h"

namespace holefill::detail {

bool move_corners(Mesh& mesh, std::vector<FaceHandle> faces, const CornerMap& corner_of,
                  const std::vector<VertexHandle>& unused) {
  std::sort(faces.begin(), faces.end(),
            [](FaceHandle a, FaceHandle b) { return a.idx() > b.idx(); });
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());

  const Mesh before = mesh;
  const DeletionFlags flags(mesh);  // after the copy: restoring it brings no flags back
  for (const auto f : faces) mesh.delete_face(f, false);
  for (const auto v : unused) mesh.delete_vertex(v, false);
  const std::size_t edges_before = mesh.n_edges();
  for (const auto old_face : faces) {
    std::array<HalfedgeHandle, 3> old_halfedges;
    std::array<VertexHandle, 3> corners;
    HalfedgeHandle h = before.halfedge_handle(old_face);
    for (int i = 0; i < 3; ++i, h = before.next_halfedge_handle(h)) {
      old_halfedges[i] = h;
      corners[i] = corner_of(old_face, before.from_vertex_handle(h));
    }
    const FaceHandle face = mesh.add_face(corners[0], corners[1], corners[2]);
    if (!face.is_valid()) {
      mesh = before;
      return false;
    }
    mesh.copy_all_properties(old_face, face, true);
    mesh.status(face).set_deleted(false);
    // The face starts at the same corner as before, so it is written out the same way.
    mesh.set_halfedge_handle(face, mesh.find_halfedge(corners[0], corners[1]));
    for (int i = 0; i < 3; ++i) {
      const HalfedgeHandle now = mesh.find_halfedge(corners[i], corners[(i + 1) % 3]);
      mesh.copy_all_properties(old_halfedges[i], now, true);
      mesh.status(now).set_deleted(false);
      const EdgeHandle edge = mesh.edge_handle(now);
      if (edge.idx() >= static_cast<int>(edges_before) &&
          mesh.is_boundary(mesh.opposite_halfedge_handle(now))) {  // made by this face
        mesh.copy_all_properties(before.edge_handle(old_halfedges[i]), edge, true);
        mesh.status(edge).set_deleted(false);
      }
    }
  }
  mesh.garbage_collection();
  return true;
}

bool merge_vertices(Mesh& mesh, const std::vector<int>& kept_of) {
  std::vector<FaceHandle> faces;
  std::vector<VertexHandle> merged;
  for (const auto v : mesh.vertices()) {
    if (kept_of[v.idx()] == v.idx()) continue;
    merged.push_back(v);
    for (const auto f : mesh.vf_range(v)) faces.push_back(f);
  }
  return move_corners(
      mesh, std::move(faces),
      [&](FaceHandle, VertexHandle v) { return VertexHandle(kept_of[v.idx()]); }, merged);
}

}  // namespace holefill::detail
