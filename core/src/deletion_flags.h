// OpenMesh marks deleted elements in status flags that garbage_collection() then removes. A Mesh
// carries none (they are 4 bytes on every vertex, edge, halfedge and face: a quarter of a big
// mesh's memory, for the rare deletion): code that deletes holds a DeletionFlags for the mesh
// from before its first delete_* call until after its garbage_collection().
#pragma once

#include "holefill/mesh.h"

namespace holefill::detail {

// Requests the mesh's status flags on construction and releases them on destruction. OpenMesh
// counts the requests, so these nest, and flags the mesh had before stay. Precondition for the
// destruction: no element is marked deleted any more (garbage_collection() ran), since the marks
// go with the flags. Assigning another mesh to `mesh` meanwhile is allowed (the flags it brings
// are then released, or none is when it has none).
class DeletionFlags {
 public:
  explicit DeletionFlags(Mesh& mesh) : mesh_(mesh) {
    mesh_.request_vertex_status();
    mesh_.request_edge_status();
    mesh_.request_halfedge_status();
    mesh_.request_face_status();
  }
  ~DeletionFlags() {
    mesh_.release_face_status();
    mesh_.release_halfedge_status();
    mesh_.release_edge_status();
    mesh_.release_vertex_status();
  }
  DeletionFlags(const DeletionFlags&) = delete;
  DeletionFlags& operator=(const DeletionFlags&) = delete;

 private:
  Mesh& mesh_;
};

// Whether the element is marked deleted: never on a mesh without status flags (a library user's
// mesh may have them, and deleted elements with them).
inline bool is_deleted(const Mesh& mesh, VertexHandle v) {
  return mesh.has_vertex_status() && mesh.status(v).deleted();
}
inline bool is_deleted(const Mesh& mesh, HalfedgeHandle h) {
  return mesh.has_halfedge_status() && mesh.status(h).deleted();
}

}  // namespace holefill::detail
