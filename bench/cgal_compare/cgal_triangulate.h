// CGAL's hole triangulation on a polyline, behind a plain interface so that CGAL's headers and
// compile options stay inside one library of this comparison program.
#pragma once

#include <array>
#include <vector>

namespace holefill::bench {

// Triangles (indices into points) of CGAL's triangulate_hole_polyline on the closed polygon
// `points`, with third_points[i] the far vertex of the mesh face across edge (i, i+1).
// delaunay = false runs its full O(n^3) search.
std::vector<std::array<int, 3>> cgal_triangulate_polyline(
    const std::vector<std::array<double, 3>>& points,
    const std::vector<std::array<double, 3>>& third_points, bool delaunay);

}  // namespace holefill::bench
