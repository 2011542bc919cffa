// OutlineGrid (core/src/outline_grid.h) answers as a pass over every edge does, by the same
// predicates: on wavy, spiky, collinear and repeated-point outlines, for points on vertices and
// edges, outside the outline's box, and at NaN.
#include "outline_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace holefill::detail {
namespace {

bool contains_by_scan(const std::vector<Point2>& outline, const Point2& p) {
  bool in = false;
  for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
    const Point2 &a = outline[i], &b = outline[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) {
      in = !in;
    }
  }
  return in;
}

bool near_by_scan(const std::vector<Point2>& outline, const Point2& p, double distance) {
  for (std::size_t i = 0; i < outline.size(); ++i) {
    if (distance_to_edge(p, outline[i], outline[(i + 1) % outline.size()]) <= distance) {
      return true;
    }
  }
  return false;
}

bool crossed_by_scan(const std::vector<Point2>& outline, const Point2& a, const Point2& b) {
  for (std::size_t i = 0; i < outline.size(); ++i) {
    if (segments_cross(a, b, outline[i], outline[(i + 1) % outline.size()])) return true;
  }
  return false;
}

std::vector<std::vector<Point2>> outlines() {
  std::vector<std::vector<Point2>> all;
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  for (const int n : {5, 40, 700}) {
    std::vector<Point2> wavy, spiky, snapped;
    for (int i = 0; i < n; ++i) {
      const double a = 2.0 * std::numbers::pi * i / n;
      const double r = 1.0 + 0.3 * std::sin(7.0 * a) + jitter(random);
      wavy.push_back({r * std::cos(a), r * std::sin(a)});
      const double s = i % 2 ? 0.2 : 1.0;  // teeth reaching across many cells
      spiky.push_back({s * std::cos(a), s * std::sin(a)});
      // On a coarse lattice: points exactly on cell bounds and edges along grid lines.
      snapped.push_back(
          {std::round(8.0 * r * std::cos(a)) / 8.0, std::round(8.0 * std::sin(a)) / 8.0});
    }
    all.push_back(wavy);
    all.push_back(spiky);
    all.push_back(snapped);
  }
  std::vector<Point2> line;  // collinear: no area
  for (int i = 0; i < 50; ++i) line.push_back({0.1 * i, 0.2 * i});
  all.push_back(line);
  all.push_back(std::vector<Point2>(30, Point2{1.0, 1.0}));  // one point repeated
  return all;
}

TEST(OutlineGrid, AnswersAsAScanOfEveryEdge) {
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> any(-1.6, 1.6);
  for (const auto& outline : outlines()) {
    SCOPED_TRACE(outline.size());
    const OutlineGrid grid(outline);
    std::vector<Point2> points(outline);                // the vertices themselves
    for (std::size_t i = 0; i < outline.size(); ++i) {  // edge midpoints
      const Point2 &a = outline[i], &b = outline[(i + 1) % outline.size()];
      points.push_back({0.5 * (a.x + b.x), 0.5 * (a.y + b.y)});
    }
    for (int i = 0; i < 2000; ++i) points.push_back({any(random), any(random)});
    points.push_back({100.0, -100.0});
    points.push_back({NAN, 0.5});
    points.push_back({0.5, NAN});
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Point2& p = points[i];
      ASSERT_EQ(grid.contains(p), contains_by_scan(outline, p)) << p.x << ' ' << p.y;
      for (const double d : {0.0, 1e-3, 0.05, 0.4}) {
        ASSERT_EQ(grid.near(p, d), near_by_scan(outline, p, d)) << p.x << ' ' << p.y << ' ' << d;
      }
      const Point2& q = points[(i * 7919 + 13) % points.size()];
      ASSERT_EQ(grid.crossed_by(p, q), crossed_by_scan(outline, p, q))
          << p.x << ' ' << p.y << " to " << q.x << ' ' << q.y;
    }
  }
}

}  // namespace
}  // namespace holefill::detail
