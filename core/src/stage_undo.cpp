#include "stage_undo.h"

#include <algorithm>
#include <atomic>

#include "deletion_flags.h"
#include "geometry.h"
#include "holefill/triangulate.h"
#include "parallel_indices.h"

namespace holefill::detail {
namespace {

// Faces looked at by one task when a large patch is looked at on several threads.
constexpr std::size_t kDegeneracyFacesPerBlock = 8192;

}  // namespace

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

bool has_degenerate_face(const Mesh& mesh, const Patch& patch, unsigned threads) {
  std::atomic<bool> found{false};
  for_each_block(patch.faces.size(), kDegeneracyFacesPerBlock, threads,
                 [&](std::size_t begin, std::size_t end, std::size_t) {
                   for (std::size_t i = begin; i < end && !found.load(std::memory_order_relaxed);
                        ++i) {
                     std::array<Point, 3> p;
                     int c = 0;
                     for (const auto v : mesh.fv_range(patch.faces[i])) p[c++ % 3] = mesh.point(v);
                     if (geometry::measure_triangle(p[0], p[1], p[2], false).degenerate) {
                       found = true;
                     }
                   }
                 });
  return found;
}

StageUndo::StageUndo(const Mesh& mesh, const Patch& patch) : patch_(patch) {
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

void StageUndo::undo(Mesh& mesh, Patch& patch) const {
  if (whole_mesh_) {
    mesh = *whole_mesh_;
    patch = patch_;
    return;
  }
  {
    const DeletionFlags flags(mesh);
    for (const auto f : patch.faces) {
      if (!mesh.status(f).deleted()) mesh.delete_face(f, false);
    }
    for (const auto v : patch.new_vertices) {
      if (!mesh.status(v).deleted()) mesh.delete_vertex(v, false);
    }
    mesh.garbage_collection();
  }
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

}  // namespace holefill::detail
