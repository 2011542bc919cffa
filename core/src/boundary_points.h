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

// A nanoflann result set: the points within `tolerance` of `centre` by the exact test
// (p - centre).norm() <= tolerance, appended to `found` in the tree's order until more than `cap`
// pass it (the search then stops).
class PointsWithinTolerance {
 public:
  PointsWithinTolerance(const BoundaryPoints& points, const Point& centre, double tolerance,
                        std::size_t cap, std::vector<std::size_t>& found)
      : points_(points),
        centre_(centre),
        tolerance_(tolerance),
        // A little wider than the tolerance: the exact test, not the tree's, decides.
        search_(std::nextafter(tolerance * tolerance * (1.0 + 1e-9), INFINITY)),
        cap_(cap),
        found_(found) {}
  double worstDist() const { return search_; }
  bool full() const { return true; }
  bool addPoint(double, std::size_t index) {
    if ((points_.mesh.point(points_.vertices[index]) - centre_).norm() <= tolerance_) {
      found_.push_back(index);
    }
    return found_.size() <= cap_;
  }

 private:
  const BoundaryPoints& points_;
  Point centre_;
  double tolerance_;
  double search_;
  std::size_t cap_;
  std::vector<std::size_t>& found_;
};

// The indices of the boundary points within `tolerance` of `centre` (exactly as
// PointsWithinTolerance tests), in `found`, in no set order. Returns false, `found` then holding
// cap + 1 of them, when more than `cap` points are that close (a crowd). A search of the
// tolerance's ball: where the ball holds a few points, a k-nearest search for cap + 1 points walked
// far beyond it (a fifth of filling 20,000 small holes, stitching and welding).
inline bool points_within_tolerance(const BoundaryIndex& index, const Point& centre,
                                    double tolerance, std::size_t cap,
                                    std::vector<std::size_t>& found) {
  found.clear();
  PointsWithinTolerance within(index.points, centre, tolerance, cap, found);
  index.tree.findNeighbors(within, centre.data(), nanoflann::SearchParams(32, 0.0f, false));
  return found.size() <= cap;
}

}  // namespace holefill::detail
