// Statistics of a patch, as the paper reports them (Table II, Fig. 6) and a user needs to judge
// a patch: counts, the valence histogram of the patch's vertices, angles and area.
#pragma once

#include <map>
#include <vector>

#include "holefill/mesh.h"
#include "holefill/patch.h"

namespace holefill {

struct PatchStats {
  std::size_t new_vertices = 0;
  std::size_t new_faces = 0;
  std::map<int, std::size_t> valence_histogram;  // valence -> number of new patch vertices
  double min_angle_deg = 0.0;                    // smallest interior angle of any patch triangle
  double mean_min_angle_deg = 0.0;  // mean over patch triangles of their smallest angle
  double max_dihedral_deg = 0.0;    // over edges of patch faces, hole boundary included
  double area = 0.0;
};

PatchStats patch_stats(const Mesh& mesh, const Patch& patch);
// The same measured on up to `threads` threads (a large patch's faces in blocks): the same stats
// on any number.
PatchStats patch_stats(const Mesh& mesh, const Patch& patch, unsigned threads);

// Valence histogram of every vertex of the mesh, for reference beside a patch's.
std::map<int, std::size_t> valence_histogram(const Mesh& mesh);

// Number of connected components (vertices joined by edges; isolated vertices count as one each).
std::size_t connected_components(const Mesh& mesh);

// The surface's pieces as a user counts them: connected components of the vertices that faces
// use, and apart from them the vertices no face uses (which connected_components counts as a
// component each: a loaded file's unused vertices would read as that many pieces).
struct SurfaceCounts {
  std::size_t components = 0;
  std::size_t unused_vertices = 0;
};
SurfaceCounts surface_counts(const Mesh& mesh);

// The connected component of each vertex (by index), numbered 0, 1, ... in order of first vertex.
std::vector<int> component_labels(const Mesh& mesh);

}  // namespace holefill
