// Step 2 of the paper: refining a patch to the density of the surrounding mesh (Liepa's
// density interpolation, Sec. II, Step 2). Triangles are split at their centroid while
// tau * |vc - vm| exceeds both sigma(vc) and sigma(vm) for every corner m, and interior patch
// edges are swapped until they are locally Delaunay (opposite angles sum to at most pi).
// With RefineOptions::remesh (not in the paper) the refined patch is then remeshed toward
// valence 6 (remesh.h).
#pragma once

#include <cmath>
#include <string>

#include "holefill/mesh.h"
#include "holefill/patch.h"
#include "holefill/progress.h"
#include "holefill/remesh.h"

namespace holefill {

struct RefineOptions {
  double tau = std::sqrt(2.0);  // density control factor; 1 <= tau <= sqrt(2) looks right
  // Safety net for absurd inputs: refinement stops (and says so) past this many patch faces.
  std::size_t max_patch_faces = 2'000'000;
  // Refinement stops (and says so) at this many times the new vertices the boundary's density
  // calls for (the patch's area over the mean boundary scale sigma squared): at tau = sqrt 2 the
  // bundled meshes' patches get 0.6-0.75 per sigma^2 of area, each doubling of tau about
  // quadruples that (31 at tau = 8), so the cap leaves tau up to about 8 alone and bounds the
  // work of larger ones (tau 1000 on a 4-edge hole ran 300 s). 0: no cap.
  double max_density = 32.0;
  // Not in the paper: remesh the refined patch toward valence 6 (see remesh.h).
  bool remesh = false;
  RemeshOptions remeshing;
  bool operator==(const RefineOptions&) const = default;
};

struct RefineResult {
  std::size_t splits = 0;
  std::size_t swaps = 0;
  bool stopped_at_face_limit = false;
  std::size_t vertex_cap = 0;  // RefineOptions::max_density's cap for this patch (0: none)
  bool stopped_at_vertex_cap = false;
  RemeshResult remeshing;  // all zero unless RefineOptions::remesh
};

// The scale sigma(v) of each boundary vertex: the mean length of its edges in the original mesh.
void assign_boundary_scales(Mesh& mesh, const Patch& patch);

// Refines the patch in place: adds vertices and faces (tagged Stage::Refined) and records them
// in `patch`. Vertices and faces outside the patch are never changed; patch.stage is left to the
// pipeline (fill.h). The splits and swaps run on a copy of the patch, written into the mesh at
// the end; std::logic_error (no element added) if patch.faces lists a face twice, which no
// stage does. Once `progress` is cancelled the splits stop within a few milliseconds and the
// mesh and the patch are left as they were (boundary scales aside); a cancel that comes after
// the splits skips the remeshing pass.
RefineResult refine_patch(Mesh& mesh, Patch& patch, const RefineOptions& options = {},
                          const Progress* progress = nullptr);

// Swaps interior patch edges until none should be swapped; returns the number of swaps. Throws
// std::logic_error, as refine_patch, if patch.faces lists a face twice.
std::size_t relax_patch_edges(Mesh& mesh, const Patch& patch);

// Refinement's relaxation test: true when the edge's two opposite angles sum to more than pi
// (the edge is not locally Delaunay) and the swapped edge's opposite angles sum to less.
bool should_swap_edge(const Mesh& mesh, EdgeHandle edge);

}  // namespace holefill
