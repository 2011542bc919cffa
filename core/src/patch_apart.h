// One hole's fill made apart from the mesh, so that many holes are filled at once (fill_groups):
// the per-hole pipeline (fill_planned: triangulation, refinement, smoothing or fairing, the
// degeneracy and intersection checks) runs on a small mesh that copies what it reads of the
// surroundings: every face at the hole's boundary vertices and at their neighbours (the fans the
// stages circulate: refinement's scale, umbrella and fairing rows up to third order, the valences
// of the statistics), and every face near the hole (its neighbourhood box, what the intersection
// checks look up). The finished patch is then spliced into the mesh, one hole after another in
// order, where the holes' work meets: a patch whose lookups or fans an earlier patch reaches, or
// whose fill hit anything out of the ordinary, is filled again in the mesh itself. So the mesh and
// every fill are the same whatever the number of threads.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "face_grid.h"
#include "holefill/fill.h"
#include "mesh_face_index.h"

namespace holefill::detail {

// A fill made apart. Its patch's handles are not the mesh's until splice_patch: boundary holds
// the mesh's vertices, faces[k] is the k-th face of `triangles`, new_vertices[k] the k-th point
// of `points`.
struct PatchApart {
  HoleFill fill;
  bool in_mesh = false;       // must be filled in the mesh itself (see the header comment)
  std::vector<Point> points;  // the new vertices, in the order they were made
  std::vector<std::uint8_t> point_stages;  // PatchTags::vertex_stage of each
  std::vector<double> point_scales;        // PatchTags::scale of each
  // The patch's faces in the order they were made; a corner >= 0 is a vertex of the mesh,
  // -1 - k the k-th new vertex.
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::uint8_t> triangle_stages;
  std::vector<double> boundary_scales;  // PatchTags::scale of each polygon vertex
  std::vector<int> fan_vertices;        // mesh vertices whose every face was read
  Box looked_up;                        // every box the checks looked up
};

// Runs fill_planned for `polygon` with `plan` on a copy of its surroundings, its patch checked
// against the faces of the mesh that `index` holds near `region` (the polygon's neighbourhood,
// one of the index's regions); `index` and the mesh are only read, so that several threads may
// share them.
PatchApart fill_apart(const Mesh& mesh, const Hole& polygon, const FillOptions& options,
                      const PlannedTriangulation& plan, const MeshFaceIndex& index,
                      const Box& region);

// What earlier splices left in the mesh, that a later patch made apart must not have read: the
// patches' faces, added to `index` (MeshFaceIndex::add) as each is spliced, and their boundaries.
class SplicedPatches {
 public:
  explicit SplicedPatches(const MeshFaceIndex& index)
      : index_(index), boundary_(index.mesh().n_vertices(), 0) {}
  // Whether `apart`, made on the mesh as it was before these patches, read any of them (its
  // lookups overlap one of their faces, or a fan it read holds one).
  bool reached_by(const PatchApart& apart) const;
  // Records the boundary of a fill now in the mesh.
  void add(const HoleFill& fill);

 private:
  const MeshFaceIndex& index_;
  std::vector<char> boundary_;  // per vertex of the mesh before the fill: on a patch's boundary
};

// Adds the patch made apart to the mesh (new vertices, then faces, in the order made, with their
// stage tags) and gives `apart.fill` the mesh's handles; false, with the mesh unchanged, when the
// mesh refuses a face.
bool splice_patch(Mesh& mesh, PatchApart& apart);

}  // namespace holefill::detail
