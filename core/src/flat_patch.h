// A patch copied out of the mesh into flat, patch-local half-edge arrays, where refinement splits
// faces and swaps edges without OpenMesh's per-element bookkeeping (properties resized per new
// element, circulators, the flip check's walk around a vertex), then written into the mesh once.
//
// The arrays follow OpenMesh's conventions exactly, so that the mesh written back is the one
// that OpenMesh's own split(face, vertex) and flip(edge) would have made, handle for handle:
// - a face's corners and edges are read from its halfedge on, along next (fv_range, fe_range);
// - new elements get the next indices of the mesh: a split's three edges in the order (b, v),
//   (c, v), (a, v) for a face a -> b -> c starting at its halfedge a -> b, each edge's first
//   halfedge pointing at v; the split face keeps a -> b, the new faces start at b -> c and c -> a;
//   the new vertex's halfedge is v -> a;
// - a flip keeps each halfedge's index and both faces' indices, and moves a vertex's halfedge
//   only where it pointed along the flipped edge.
// Local faces are numbered as the patch lists them (Patch::faces), new ones appended as a split
// hands them to the patch: the face ahead of the split face's halfedge (c -> a) first, which is
// the order OpenMesh's vf_range(v) visits them.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "flat_index_map.h"
#include "holefill/mesh.h"
#include "holefill/patch.h"

namespace holefill::detail {

// One bit per face, and a quick way to the next face whose bit is set.
class FaceFlags {
 public:
  void grow(int faces) { words_.resize((static_cast<std::size_t>(faces) + 63) / 64, 0); }
  void set(int face) { words_[face >> 6] |= bit(face); }
  void clear(int face) { words_[face >> 6] &= ~bit(face); }
  // The first face from `face` on whose bit is set, or `end` when none is below `end`.
  int next(int face, int end) const;

 private:
  static std::uint64_t bit(int face) { return std::uint64_t{1} << (face & 63); }
  std::vector<std::uint64_t> words_;
};

class FlatPatch {
 public:
  // Copies the patch's faces (distinct, as every stage makes them), their edges and vertices,
  // with each vertex's `scale` (0 where the handle is invalid). Throws std::logic_error when the
  // patch lists a face twice. The mesh must not change until write_back.
  FlatPatch(const Mesh& mesh, const Patch& patch, OpenMesh::VPropHandleT<double> scale);

  int face_count() const { return static_cast<int>(face_halfedge_.size()); }
  int new_vertex_count() const { return static_cast<int>(points_.size()) - loaded_vertices_; }
  const Point& point(int vertex) const { return points_[vertex]; }
  double scale(int vertex) const { return scales_[vertex]; }

  // The face's corners, as the mesh's fv_range lists them.
  std::array<int, 3> corners(int face) const;
  // The face's edges, as the mesh's fe_range lists them.
  std::array<int, 3> edges(int face) const;

  // The first face from `face` on (below `end`, else `end`) that is new or changed since
  // settle_face() marked it: positions and scales never change, so a face that refinement tested
  // and left would be left again.
  int next_untested(int face, int end) const { return untested_.next(face, end); }
  void settle_face(int face) { untested_.clear(face); }

  // Splits the face at a new vertex (position, scale): OpenMesh's split(face, vertex). Appends
  // two faces and marks all three as refined.
  void split(int face, const Point& position, double scale);

  // Whether refinement swaps the edge: both its faces are the patch's, should_swap_quad says so
  // and the swapped edge is not in the mesh yet (OpenMesh's is_flip_ok). The geometric test's
  // "no" is remembered until a split or flip changes one of the edge's faces: relaxation sweeps
  // the whole patch after every round, and most edges are long settled.
  bool swappable(int edge);
  // OpenMesh's flip(edge); the edge must be swappable.
  void flip(int edge);
  // Swaps edges, face by face and edge by edge, in sweeps until a sweep swaps none or after
  // `max_sweeps`; returns the number of swaps.
  std::size_t relax(int max_sweeps);

  // Writes the patch into the mesh: the new vertices (with scale and Stage::Refined in `tags`)
  // and faces, the split faces' stage, every patch halfedge's links; appends the new faces and
  // vertices to `patch` in their local order. Call once, on the mesh it was copied from (else
  // std::logic_error).
  void write_back(Mesh& mesh, const PatchTags& tags, Patch& patch) const;
  // The same for a patch that only had edges swapped (no tags needed).
  void write_links(Mesh& mesh) const;

 private:
  int add_vertex(const Mesh& mesh, VertexHandle vertex, OpenMesh::VPropHandleT<double> scale);
  int local_halfedge(const Mesh& mesh, HalfedgeHandle halfedge,
                     OpenMesh::VPropHandleT<double> scale);
  int add_edge(int from, int to, int handle);
  int add_face(int halfedge, int handle);
  int global_halfedge(int halfedge) const {
    return 2 * edge_handle_[halfedge >> 1] + (halfedge & 1);
  }
  void count_edge(int a, int b, int change);
  bool has_edge(int a, int from_a, int b, int from_b) const;
  bool has_outside_edge(int a, int b) const;
  void link(int h0, int h1, int h2, int face);
  void unsettle_edge(int edge);

  const Mesh& mesh_;
  int mesh_vertices_, mesh_edges_, mesh_faces_;  // the mesh's counts when copied
  int loaded_vertices_ = 0, loaded_edges_ = 0, loaded_faces_ = 0;
  // Per vertex; handles are the mesh's indices (new elements' are those they will get).
  std::vector<Point> points_;
  std::vector<double> scales_;
  std::vector<int> vertex_handle_;
  std::vector<int> vertex_halfedge_;  // the mesh's index of its outgoing halfedge
  // Per halfedge (2e, 2e + 1 for edge e); next_ and face_ are -1 outside the patch.
  std::vector<int> next_, to_, face_;
  // Per edge.
  std::vector<int> edge_handle_;
  std::vector<std::uint8_t> edge_settled_;  // should_swap_quad said no, and the quad is the same
  // Per face.
  std::vector<int> face_halfedge_, face_handle_;
  std::vector<std::uint8_t> refined_;
  FaceFlags untested_;          // see next_untested()
  FaceFlags unsettled_;         // one of the face's edges is not settled
  FlatIndexMap edge_index_;     // the mesh's edge index -> loaded edge
  FlatIndexMap vertex_index_;   // the mesh's vertex index -> loaded vertex
  FlatIndexMap edges_between_;  // two loaded vertices -> number of patch edges joining them
};

}  // namespace holefill::detail
