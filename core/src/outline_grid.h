// A closed 2D outline (a hole's loop projected onto its plane, islands.cpp) filed in a uniform
// grid of about as many cells as it has edges, so that asking about a point or a segment tests
// the edges near it rather than every edge: comparing two 65,535-edge loops edge by edge took
// 13 s, a 200,000-edge loop against its neighbour 118 s. Each answer is the one a pass over
// every edge gives, by the same arithmetic: the grid only leaves out edges that cannot count.
// Edges spanning many cells are filed in each; an outline whose edges all span the whole grid
// (a comb of long teeth) is as slow as the pass over every edge, never slower than twice.
#pragma once

#include <cstddef>
#include <vector>

namespace holefill::detail {

struct Point2 {
  double x, y;
};

class OutlineGrid {
 public:
  // Files the edges (outline[i], outline[i + 1]) and the closing one. Empty or non-finite
  // outlines answer by passing over every edge.
  explicit OutlineGrid(const std::vector<Point2>& outline);

  // Even-odd rule: the horizontal ray from p to the right crosses the outline an odd number of
  // times (as islands.cpp's inside()).
  bool contains(const Point2& p) const;

  // Some edge comes within `distance` of p (the distance of p to the segment, at most).
  bool near(const Point2& p, double distance) const;

  // The edges within `distance` of p, for callers that measure otherwise (appended, ascending).
  void edges_near(const Point2& p, double distance, std::vector<int>& edges) const;

  // Some edge crosses the segment ab properly (each one's ends strictly on both sides of the
  // other's line).
  bool crossed_by(const Point2& a, const Point2& b) const;

 private:
  // The grid's cells [first, last] in x and y that the box from (x0, y0) to (x1, y1) touches
  // (clamped to the grid); false when the box misses the grid.
  bool cells(double x0, double y0, double x1, double y1, int range[4]) const;
  // Every edge filed in the cells of `range`, each once (ascending).
  void edges_in(const int range[4], std::vector<int>& edges) const;

  const std::vector<Point2>& outline_;
  bool whole_ = true;  // no grid: every question passes over every edge
  double x0_ = 0.0, y0_ = 0.0, cell_ = 1.0;
  int columns_ = 1, rows_ = 1;
  std::vector<int> row_start_;  // rows: edges crossing each row's span of y
  std::vector<int> row_edges_;
  std::vector<int> cell_start_;  // cells: edges whose box touches each cell
  std::vector<int> cell_edges_;
  mutable std::vector<int> seen_;  // the last query that collected each edge
  mutable int query_ = 0;
};

// Distance from p to the segment ab (lifted into 3D with z = 0, as islands.cpp measures).
double distance_to_edge(const Point2& p, const Point2& a, const Point2& b);

// Cross product of (a - o) and (b - o).
inline double cross2(const Point2& o, const Point2& a, const Point2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Segments ab and cd cross properly.
inline bool segments_cross(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double abc = cross2(a, b, c), abd = cross2(a, b, d);
  const double cda = cross2(c, d, a), cdb = cross2(c, d, b);
  return ((abc > 0) != (abd > 0)) && ((cda > 0) != (cdb > 0));
}

}  // namespace holefill::detail
