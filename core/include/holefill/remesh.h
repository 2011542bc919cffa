// Remeshing a refined patch toward valence 6 (not in the paper; an option of the refine stage).
// Centroid splits with Delaunay swaps leave a mix of valences 5, 6 and 7; a few rounds of
//   (a) valence-driven edge flips on the patch's interior edges: flip when it lowers the sum of
//       squared deviations from each corner's target valence (6 for new vertices; for a hole's
//       boundary vertex, its valence in the whole mesh when the patch side gets triangles of
//       about 60 degrees: the share of 6 that the patch side's angle is of the vertex's angle), and
//   (b) tangential relaxation: each new vertex moves to the mean of its neighbours, within its
//       tangent plane,
// make most new vertices regular, as in isotropic remeshing (Botsch & Kobbelt 2004), without
// splits or collapses: the vertex count stays what the paper's density rule chose.
// Only interior patch edges flip and only new vertices move; the boundary loop and the rest of
// the mesh never change. A flip is refused when the swapped edge exists already, or when it
// makes a degenerate or folded triangle, a dihedral angle above max_flip_dihedral_deg (or above
// the one it replaces, if that is larger) or an angle below 20 degrees (unless the pair had one);
// a move is refused when it would degenerate or turn over one of the vertex's faces, or give
// them an angle below 20 degrees (unless they had one).
#pragma once

#include <cstddef>

#include "holefill/mesh.h"
#include "holefill/patch.h"

namespace holefill {

struct RemeshOptions {
  int iterations = 5;                 // rounds of flips then relaxation
  double max_flip_dihedral_deg = 30;  // between the two triangles a flip makes
  bool operator==(const RemeshOptions&) const = default;
};

struct RemeshResult {
  std::size_t flips = 0;
  std::size_t moves = 0;  // vertex moves, over all rounds
};

// The valence a vertex of the patch should have in the whole mesh.
int target_valence(const Mesh& mesh, const Patch& patch, VertexHandle vertex);

// Remeshes the patch in place: its faces and new vertices keep their handles (so `patch` stays
// valid as it is), faces a flip changed are tagged Stage::Refined. Does nothing on a patch
// without new vertices (the triangulation's own optimum is left as it is).
RemeshResult remesh_patch(Mesh& mesh, const Patch& patch, const RemeshOptions& options = {});

}  // namespace holefill
