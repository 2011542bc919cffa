#include "outline_grid.h"

#include <algorithm>
#include <cmath>

namespace holefill::detail {
namespace {

constexpr int kMostCellsPerSide = 4096;

// Room for rounding: a query's box is widened by this fraction of the grid's extent, so that an
// edge whose test passes by a rounding error is among those tested.
constexpr double kMargin = 1e-9;

double clamp_index(double value, int count) {
  return std::clamp(value, 0.0, static_cast<double>(count - 1));
}

}  // namespace

double distance_to_edge(const Point2& p, const Point2& a, const Point2& b) {
  // As islands.cpp's distance_to_segment on points lifted to z = 0.
  const double abx = b.x - a.x, aby = b.y - a.y;
  const double length2 = abx * abx + aby * aby;
  const double t =
      length2 > 0.0 ? std::clamp(((p.x - a.x) * abx + (p.y - a.y) * aby) / length2, 0.0, 1.0) : 0.0;
  const double dx = p.x - (a.x + t * abx), dy = p.y - (a.y + t * aby);
  return std::sqrt(dx * dx + dy * dy);
}

OutlineGrid::OutlineGrid(const std::vector<Point2>& outline) : outline_(outline) {
  const std::size_t n = outline.size();
  if (n < 16) return;  // a pass over a few edges is as quick
  double x1 = -INFINITY, y1 = -INFINITY;
  x0_ = y0_ = INFINITY;
  for (const auto& p : outline) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    x0_ = std::min(x0_, p.x), y0_ = std::min(y0_, p.y);
    x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  }
  const double extent = std::max(x1 - x0_, y1 - y0_);
  const int side = std::min(kMostCellsPerSide, static_cast<int>(std::ceil(std::sqrt(n))));
  cell_ = extent / side;
  if (!(cell_ > 0.0) || !std::isfinite(cell_)) return;
  columns_ = std::max(1, std::min(side, static_cast<int>((x1 - x0_) / cell_) + 1));
  rows_ = std::max(1, std::min(side, static_cast<int>((y1 - y0_) / cell_) + 1));
  // Counted, then filed (compressed rows: no vector per cell).
  row_start_.assign(static_cast<std::size_t>(rows_) + 1, 0);
  cell_start_.assign(static_cast<std::size_t>(rows_) * columns_ + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t i = 0; i < n; ++i) {
      const Point2 &a = outline[i], &b = outline[(i + 1) % n];
      int range[4];
      cells(std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y), range);
      for (int r = range[2]; r <= range[3]; ++r) {
        if (pass == 0) {
          ++row_start_[r + 1];
        } else {
          row_edges_[row_start_[r]++] = static_cast<int>(i);
        }
        for (int c = range[0]; c <= range[1]; ++c) {
          const std::size_t at = static_cast<std::size_t>(r) * columns_ + c;
          if (pass == 0) {
            ++cell_start_[at + 1];
          } else {
            cell_edges_[cell_start_[at]++] = static_cast<int>(i);
          }
        }
      }
    }
    if (pass == 0) {
      for (std::size_t r = 1; r < row_start_.size(); ++r) row_start_[r] += row_start_[r - 1];
      for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
      row_edges_.resize(static_cast<std::size_t>(row_start_.back()));
      cell_edges_.resize(static_cast<std::size_t>(cell_start_.back()));
    }
  }
  // The filing moved each start to the next one's: put them back.
  std::rotate(row_start_.rbegin(), row_start_.rbegin() + 1, row_start_.rend());
  row_start_[0] = 0;
  std::rotate(cell_start_.rbegin(), cell_start_.rbegin() + 1, cell_start_.rend());
  cell_start_[0] = 0;
  seen_.assign(n, -1);
  whole_ = false;
}

bool OutlineGrid::cells(double x0, double y0, double x1, double y1, int range[4]) const {
  // The index is monotone in the coordinate (subtraction and division round monotonically), so
  // a point between an edge's ends lies in a cell between theirs.
  if (std::isnan(x0) || std::isnan(y0) || std::isnan(x1) || std::isnan(y1)) return false;
  range[0] = static_cast<int>(clamp_index(std::floor((x0 - x0_) / cell_), columns_));
  range[1] = static_cast<int>(clamp_index(std::floor((x1 - x0_) / cell_), columns_));
  range[2] = static_cast<int>(clamp_index(std::floor((y0 - y0_) / cell_), rows_));
  range[3] = static_cast<int>(clamp_index(std::floor((y1 - y0_) / cell_), rows_));
  return true;
}

void OutlineGrid::edges_in(const int range[4], std::vector<int>& edges) const {
  const std::size_t first = edges.size();
  if (++query_ == 0) std::fill(seen_.begin(), seen_.end(), -1);  // wrapped: start afresh
  for (int r = range[2]; r <= range[3]; ++r) {
    for (int c = range[0]; c <= range[1]; ++c) {
      const std::size_t at = static_cast<std::size_t>(r) * columns_ + c;
      for (int k = cell_start_[at]; k < cell_start_[at + 1]; ++k) {
        const int edge = cell_edges_[k];
        if (seen_[edge] == query_) continue;
        seen_[edge] = query_;
        edges.push_back(edge);
      }
    }
  }
  std::sort(edges.begin() + static_cast<std::ptrdiff_t>(first), edges.end());
}

bool OutlineGrid::contains(const Point2& p) const {
  const std::size_t n = outline_.size();
  bool in = false;
  auto cross = [&](std::size_t i) {
    // Each edge taken from its second end, as islands.cpp's scan did: at a vertex the crossing's
    // rounding depends on the end it starts from.
    const Point2 &a = outline_[(i + 1) % n], &b = outline_[i];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) {
      in = !in;
    }
  };
  if (whole_ || std::isnan(p.y)) {
    for (std::size_t i = 0; i < n; ++i) cross(i);
    return in;
  }
  // Only an edge whose y-range holds p.y can cross the ray, and it is filed under p's row.
  const int row = static_cast<int>(clamp_index(std::floor((p.y - y0_) / cell_), rows_));
  for (int k = row_start_[row]; k < row_start_[row + 1]; ++k) cross(row_edges_[k]);
  return in;
}

void OutlineGrid::edges_near(const Point2& p, double distance, std::vector<int>& edges) const {
  if (whole_ || !(distance < INFINITY)) {
    for (std::size_t i = 0; i < outline_.size(); ++i) edges.push_back(static_cast<int>(i));
    return;
  }
  const double reach = distance * (1.0 + kMargin) + kMargin * cell_ * std::max(columns_, rows_);
  int range[4];
  if (!cells(p.x - reach, p.y - reach, p.x + reach, p.y + reach, range)) {
    for (std::size_t i = 0; i < outline_.size(); ++i) edges.push_back(static_cast<int>(i));
    return;
  }
  edges_in(range, edges);
}

bool OutlineGrid::near(const Point2& p, double distance) const {
  std::vector<int> edges;
  edges_near(p, distance, edges);
  const std::size_t n = outline_.size();
  return std::any_of(edges.begin(), edges.end(), [&](int i) {
    return distance_to_edge(p, outline_[i], outline_[(i + 1) % n]) <= distance;
  });
}

bool OutlineGrid::crossed_by(const Point2& a, const Point2& b) const {
  const std::size_t n = outline_.size();
  auto crosses = [&](std::size_t i) {
    return segments_cross(a, b, outline_[i], outline_[(i + 1) % n]);
  };
  int range[4];
  const double margin = kMargin * cell_ * std::max(columns_, rows_);
  if (whole_ || !cells(std::min(a.x, b.x) - margin, std::min(a.y, b.y) - margin,
                       std::max(a.x, b.x) + margin, std::max(a.y, b.y) + margin, range)) {
    for (std::size_t i = 0; i < n; ++i) {
      if (crosses(i)) return true;
    }
    return false;
  }
  std::vector<int> edges;
  edges_in(range, edges);
  return std::any_of(edges.begin(), edges.end(), [&](int i) { return crosses(i); });
}

}  // namespace holefill::detail
