// The boundary vertices of a mesh in a k-d tree (nanoflann), for the searches of stitch.cpp and
// t_junctions.cpp: which boundary vertices lie near a point.
#pragma once

#include <cmath>
#include <nanoflann.hpp>
#include <utility>
#include <vector>

#include "holefill/mesh.h"

namespace holefill::detail {

// The boundary vertices' positions as nanoflann's dataset adaptor wants them.
struct BoundaryPoints {
  const Mesh& mesh;
  std::vector<VertexHandle> vertices;

  std::size_t kdtree_get_point_count() const { return vertices.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t axis) const {
    return mesh.point(vertices[i])[static_cast<int>(axis)];
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using BoundaryPointTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, BoundaryPoints>,
                                        BoundaryPoints, 3, std::size_t>;

// Every vertex that ends a boundary halfedge, each once, in the order of the halfedges.
inline BoundaryPoints boundary_points(const Mesh& mesh) {
  BoundaryPoints points{mesh, {}};
  std::vector<char> listed(mesh.n_vertices(), 0);
  for (const auto h : mesh.halfedges()) {
    const VertexHandle to = mesh.to_vertex_handle(h);
    if (!mesh.is_boundary(h) || listed[to.idx()]) continue;
    listed[to.idx()] = 1;
    points.vertices.push_back(to);
  }
  return points;
}

// A mesh's boundary points and their k-d tree, built once for the searches of one stitch (the
// tree's build is a good part of stitching a mesh whose every vertex is on a boundary). The tree
// refers to `points`: an index stays where it was made.
struct BoundaryIndex {
  explicit BoundaryIndex(const Mesh& mesh)
      : points(boundary_points(mesh)),
        tree(3, points, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {
    if (!points.vertices.empty()) tree.buildIndex();
  }
  BoundaryIndex(const BoundaryIndex&) = delete;
  BoundaryIndex& operator=(const BoundaryIndex&) = delete;

  BoundaryPoints points;
  BoundaryPointTree tree;
};

// The indices (into points.vertices) of the points within `radius` of `centre`, possibly with a
// few just outside it: nanoflann keeps points strictly inside the squared radius, so the search
// is widened by one ulp and callers test the exact distance they need.
inline void points_near(const BoundaryPointTree& tree, const Point& centre, double radius,
                        std::vector<std::pair<std::size_t, double>>& found) {
  found.clear();
  const double search_radius = std::nextafter(radius * radius, INFINITY);
  tree.radiusSearch(centre.data(), search_radius, found, nanoflann::SearchParams(32, 0.0f, false));
}

}  // namespace holefill::detail
