// The reference to beat: CGAL's Polygon_mesh_processing::triangulate_refine_and_fair_hole
// (Liepa 2003: triangulate, refine, fair; CGAL's defaults: Delaunay-restricted search space,
// density factor sqrt 2, C1 fairing with cotangent weights and Voronoi areas), run on a
// Surface_mesh copy of the same cut mesh. Built only when CMake finds CGAL.
//
// The interface is plain arrays, so that this translation unit (compiled with CGAL's
// -frounding-math) does not include OpenMesh.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace holefill::quality {

struct PlainMesh {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<int, 3>> faces;
};

struct CgalPatch {
  std::vector<int> faces;         // indices into the filled mesh's faces
  std::vector<int> new_vertices;  // indices into its points
  bool faired = false;            // CGAL's own report
};

struct CgalFill {
  PlainMesh mesh;  // the cut mesh's points and faces (same indices), then the patches'
  std::vector<CgalPatch> patches;
};

// Fills the hole on the border of each directed edge (from, to), given as a boundary edge of
// `cut` running along its hole like holefill's Hole::halfedges.
CgalFill cgal_fill(const PlainMesh& cut, const std::vector<std::array<int, 2>>& hole_edges);

// CGAL's fairing alone (Polygon_mesh_processing::fair, C1, its default weights) of the given
// vertices of `mesh`, in place; false (positions unchanged) where CGAL reports failure.
bool cgal_fair(PlainMesh& mesh, const std::vector<int>& vertices);

}  // namespace holefill::quality
