#include "cgal_triangulate.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <iterator>

namespace holefill::bench {

std::vector<std::array<int, 3>> cgal_triangulate_polyline(
    const std::vector<std::array<double, 3>>& points,
    const std::vector<std::array<double, 3>>& third_points, bool delaunay) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using CgalPoint = Kernel::Point_3;
  std::vector<CgalPoint> polyline, thirds;
  for (const auto& p : points) polyline.emplace_back(p[0], p[1], p[2]);
  for (const auto& p : third_points) thirds.emplace_back(p[0], p[1], p[2]);
  std::vector<CGAL::Triple<int, int, int>> patch;
  CGAL::Polygon_mesh_processing::triangulate_hole_polyline(
      polyline, thirds, std::back_inserter(patch),
      CGAL::parameters::use_delaunay_triangulation(delaunay)
          .use_2d_constrained_delaunay_triangulation(false));
  std::vector<std::array<int, 3>> triangles;
  for (const auto& t : patch) triangles.push_back({t.first, t.second, t.third});
  return triangles;
}

}  // namespace holefill::bench
