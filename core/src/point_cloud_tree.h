// Points in a k-d tree (nanoflann), shared by the searches that ask which of a list of points lie
// near another: the restricted search's nearest neighbours (nearest_neighbours.cpp) and the loops
// near each hole (islands.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <nanoflann.hpp>
#include <vector>

#include "holefill/mesh.h"

namespace holefill::detail {

// The points as nanoflann reads them; `points` must outlive the tree built on them.
struct PointCloud {
  const std::vector<Point>& points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::uint32_t i, std::size_t axis) const {
    return points[i][static_cast<int>(axis)];
  }
  template <class Box>
  bool kdtree_get_bbox(Box& /*box*/) const {
    return false;  // let the tree compute it
  }
};

using PointCloudTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>,
                                        PointCloud, 3, std::uint32_t>;

}  // namespace holefill::detail
