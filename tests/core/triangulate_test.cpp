// The dynamic program against independent truths: brute-force enumeration of every
// triangulation of small polygons, and the Delaunay triangulation of planar convex polygons.
#include "holefill/triangulate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>

#include "geometry.h"
#include "test_meshes.h"

namespace holefill {
namespace {

using Triangles = std::vector<std::array<int, 3>>;

// Every triangulation of the sub-polygon i..k that uses no forbidden chord.
std::vector<Triangles> all_triangulations(int i, int k,
                                          const std::set<std::pair<int, int>>& forbidden, int n) {
  if (k - i < 2) return {Triangles{}};
  if (forbidden.count({i, k}) && !(i == 0 && k == n - 1)) return {};
  std::vector<Triangles> result;
  for (int m = i + 1; m < k; ++m) {
    for (const auto& left : all_triangulations(i, m, forbidden, n)) {
      for (const auto& right : all_triangulations(m, k, forbidden, n)) {
        Triangles t = left;
        t.insert(t.end(), right.begin(), right.end());
        t.push_back({i, m, k});
        result.push_back(std::move(t));
      }
    }
  }
  return result;
}

HolePolygon random_hole(int n, std::mt19937& rng) {
  HolePolygon polygon;
  polygon.points = testing::random_loop(n, rng, 0.35, 0.4);
  // The surrounding surface leans outwards and downwards, as around a hole in a curved mesh.
  for (int i = 0; i < n; ++i) {
    const Point mid = (polygon.points[i] + polygon.points[(i + 1) % n]) * 0.5;
    polygon.outside_normals.push_back(
        (Point(0, 0, 1) + 0.4 * Point(mid[0], mid[1], 0)).normalized());
  }
  return polygon;
}

std::vector<std::pair<int, int>> random_forbidden_chords(int n, std::mt19937& rng) {
  std::vector<std::pair<int, int>> chords;
  std::bernoulli_distribution pick(0.15);
  for (int i = 0; i < n; ++i) {
    for (int k = i + 2; k < n; ++k) {
      if (!(i == 0 && k == n - 1) && pick(rng)) chords.emplace_back(i, k);
    }
  }
  return chords;
}

TEST(Triangulate, AreaWeightMatchesBruteForceOnSmallPolygons) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 3 + trial % 7;  // 3 ... 9
    HolePolygon polygon = random_hole(n, rng);
    polygon.forbidden_chords = random_forbidden_chords(n, rng);
    const std::set<std::pair<int, int>> forbidden(polygon.forbidden_chords.begin(),
                                                  polygon.forbidden_chords.end());
    const auto candidates = all_triangulations(0, n - 1, forbidden, n);
    const auto dp = triangulate_polygon(polygon, {WeightKind::Area});
    ASSERT_EQ(dp.has_value(), !candidates.empty()) << "trial " << trial;
    if (!dp) continue;
    double best = INFINITY;
    for (const auto& t : candidates) best = std::min(best, evaluate_triangulation(polygon, t).area);
    EXPECT_NEAR(dp->quality.area, best, 1e-12 * best) << "trial " << trial << ", n = " << n;
  }
}

TEST(Triangulate, MaxMinMaximisesTheSmallestAngleLikeBruteForce) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 3 + trial % 7;
    HolePolygon polygon = random_hole(n, rng);
    polygon.forbidden_chords = random_forbidden_chords(n, rng);
    const std::set<std::pair<int, int>> forbidden(polygon.forbidden_chords.begin(),
                                                  polygon.forbidden_chords.end());
    const auto candidates = all_triangulations(0, n - 1, forbidden, n);
    // The paper's order (no fold limit) maximises the smallest angle outright.
    const auto dp = triangulate_polygon(polygon, {WeightKind::MaxMin, std::numbers::pi});
    ASSERT_EQ(dp.has_value(), !candidates.empty());
    if (!dp) continue;
    double best = 0.0;
    for (const auto& t : candidates) {
      best = std::max(best, evaluate_triangulation(polygon, t).min_angle);
    }
    // Optimal up to the quantisation of angles in the weight's key.
    EXPECT_NEAR(dp->quality.min_angle, best, kAngleResolution)
        << "trial " << trial << ", n = " << n;
  }
}

// With four corners each side of the root triangle has a single triangulation, so the dynamic
// program's dihedral terms are exact: every weight must find the optimum under its full order.
TEST(Triangulate, EveryWeightIsOptimalUnderItsFullOrderOnQuadrilaterals) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 200; ++trial) {
    const HolePolygon polygon = random_hole(4, rng);
    const Triangles split_02{{0, 1, 2}, {0, 2, 3}}, split_13{{1, 2, 3}, {0, 1, 3}};
    const auto q02 = evaluate_triangulation(polygon, split_02);
    const auto q13 = evaluate_triangulation(polygon, split_13);
    const TriangulateOptions maxmin_options{WeightKind::MaxMin, std::numbers::pi};
    const TriangulateOptions liepa_options{WeightKind::Liepa};
    const auto maxmin = triangulate_polygon(polygon, maxmin_options);
    const auto liepa = triangulate_polygon(polygon, liepa_options);
    ASSERT_TRUE(maxmin && liepa);
    const bool maxmin_prefers_02 =
        weight_value(q02, maxmin_options) < weight_value(q13, maxmin_options);
    const bool liepa_prefers_02 =
        weight_value(q02, liepa_options) < weight_value(q13, liepa_options);
    EXPECT_NEAR(maxmin->quality.min_angle, (maxmin_prefers_02 ? q02 : q13).min_angle, 1e-12);
    EXPECT_NEAR(maxmin->quality.max_dihedral, (maxmin_prefers_02 ? q02 : q13).max_dihedral, 1e-12);
    EXPECT_NEAR(liepa->quality.max_dihedral, (liepa_prefers_02 ? q02 : q13).max_dihedral, 1e-12);
    EXPECT_NEAR(liepa->quality.area, (liepa_prefers_02 ? q02 : q13).area, 1e-12);
  }
}

// Delaunay maximises the smallest angle over all triangulations of a point set; for a convex
// polygon those are exactly the polygon's triangulations.
TEST(Triangulate, MaxMinOnPlanarConvexPolygonMatchesDelaunayMinAngle) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 5 + trial;
    std::vector<double> angles;
    for (int i = 0; i < n; ++i) angles.push_back(2.0 * std::numbers::pi * unit(rng));
    std::sort(angles.begin(), angles.end());
    HolePolygon polygon;
    for (const double a : angles) polygon.points.emplace_back(2.0 * std::cos(a), std::sin(a), 0.0);
    polygon.outside_normals.assign(n, Point(0, 0, 1));

    // Brute-force Delaunay: triangles whose circumcircle holds no other point.
    double delaunay_min_angle = std::numbers::pi;
    const auto& p = polygon.points;
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        for (int k = j + 1; k < n; ++k) {
          const double ax = p[i][0], ay = p[i][1], bx = p[j][0], by = p[j][1], cx = p[k][0],
                       cy = p[k][1];
          const double d = 2.0 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by));
          if (std::abs(d) < 1e-14) continue;
          const double ux = ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay) +
                             (cx * cx + cy * cy) * (ay - by)) /
                            d;
          const double uy = ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx) +
                             (cx * cx + cy * cy) * (bx - ax)) /
                            d;
          const double r2 = (ax - ux) * (ax - ux) + (ay - uy) * (ay - uy);
          bool empty = true;
          for (int m = 0; m < n && empty; ++m) {
            if (m == i || m == j || m == k) continue;
            const double d2 = (p[m][0] - ux) * (p[m][0] - ux) + (p[m][1] - uy) * (p[m][1] - uy);
            if (d2 < r2 * (1.0 - 1e-12)) empty = false;
          }
          if (empty) {
            delaunay_min_angle = std::min(delaunay_min_angle,
                                          geometry::measure_triangle(p[i], p[j], p[k]).min_angle);
          }
        }
      }
    }
    const auto dp = triangulate_polygon(polygon, {WeightKind::MaxMin});
    ASSERT_TRUE(dp);
    EXPECT_NEAR(dp->quality.min_angle, delaunay_min_angle, kAngleResolution) << "n = " << n;
    EXPECT_NEAR(dp->quality.max_dihedral, 0.0, 1e-12);  // planar: the patch stays flat
  }
}

TEST(Triangulate, PrunedSearchGivesTheSameTriangulationAsThePlainLoop) {
  std::mt19937 rng(23);
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 3 + trial * 3;
    HolePolygon polygon = random_hole(n, rng);
    if (trial % 2) polygon.forbidden_chords = random_forbidden_chords(n, rng);
    for (const auto weight : {WeightKind::MaxMin, WeightKind::Liepa, WeightKind::Area}) {
      TriangulateOptions fast{weight}, plain{weight};
      plain.prune = false;
      const auto a = triangulate_polygon(polygon, fast), b = triangulate_polygon(polygon, plain);
      ASSERT_EQ(a.has_value(), b.has_value());
      if (!a) continue;
      EXPECT_EQ(a->triangles, b->triangles) << to_string(weight) << ", n = " << n;
    }
  }
}

// The pruned search tries apexes in another order (a seed first) and skips most of them on bounds;
// on large holes, with forbidden chords, with either fold limit and with exact ties (a regular
// planar polygon, where many triangulations have the same smallest angle), it must still pick
// exactly the plain loop's triangulation.
TEST(Triangulate, PrunedSearchMatchesThePlainLoopOnLargeAndTiedHoles) {
  std::mt19937 rng(41);
  std::vector<HolePolygon> polygons;
  for (const int n : {150, 240}) {
    polygons.push_back(random_hole(n, rng));
    polygons.push_back(random_hole(n, rng));
    polygons.back().forbidden_chords = random_forbidden_chords(n, rng);
  }
  HolePolygon regular;
  for (int i = 0; i < 40; ++i) {
    regular.points.emplace_back(std::cos(2.0 * std::numbers::pi * i / 40),
                                std::sin(2.0 * std::numbers::pi * i / 40), 0.0);
  }
  regular.outside_normals.assign(40, Point(0, 0, 1));
  polygons.push_back(regular);
  for (const auto& polygon : polygons) {
    for (const auto weight : {WeightKind::MaxMin, WeightKind::Liepa, WeightKind::Area}) {
      for (const double fold_limit : {kDefaultFoldLimit, std::numbers::pi}) {
        TriangulateOptions fast{weight, fold_limit}, plain{weight, fold_limit};
        fast.restricted.above_edges = plain.restricted.above_edges = 0;
        plain.prune = false;
        const auto a = triangulate_polygon(polygon, fast), b = triangulate_polygon(polygon, plain);
        ASSERT_EQ(a.has_value(), b.has_value());
        if (!a) continue;
        EXPECT_EQ(a->triangles, b->triangles)
            << to_string(weight) << ", n = " << polygon.points.size() << ", fold " << fold_limit;
      }
    }
  }
}

// A triangulation of polygon 0..n-1: n-2 triangles, each polygon edge in exactly one of them,
// each chord in exactly two, all oriented like the polygon.
bool is_polygon_triangulation(int n, const Triangles& triangles) {
  if (static_cast<int>(triangles.size()) != n - 2) return false;
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : triangles) {
    if (!(t[0] < t[1] && t[1] < t[2])) return false;
    for (int e = 0; e < 3; ++e) ++directed[{t[e], t[(e + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    const auto [a, b] = edge;
    const bool polygon_edge = (b == a + 1) || (a == n - 1 && b == 0);
    const int reverse = directed.count({b, a}) ? directed.at({b, a}) : 0;
    if (count != 1 || (polygon_edge ? reverse != 0 : reverse != 1)) return false;
  }
  return true;
}

// Callers of the public API may pass outside normals of any length; the weights compare angles,
// so only their directions may count.
TEST(Triangulate, OutsideNormalsOfAnyLengthCountOnlyByDirection) {
  std::mt19937 rng(43);
  for (const int n : {12, 60}) {
    const HolePolygon unit = random_hole(n, rng);
    HolePolygon scaled = unit;
    for (std::size_t i = 0; i < scaled.outside_normals.size(); ++i) {
      scaled.outside_normals[i] *= (i % 3 == 0 ? 2.5 : (i % 3 == 1 ? 1e-3 : 1.0));
    }
    for (const auto weight : {WeightKind::MaxMin, WeightKind::Liepa}) {
      TriangulateOptions options{weight};
      const auto a = triangulate_polygon(unit, options), b = triangulate_polygon(scaled, options);
      ASSERT_TRUE(a && b);
      EXPECT_EQ(a->triangles, b->triangles) << to_string(weight) << ", n = " << n;
      const auto c = triangulate_polygon_restricted(unit, options);
      const auto d = triangulate_polygon_restricted(scaled, options);
      ASSERT_TRUE(c && d);
      EXPECT_EQ(c->triangles, d->triangles) << to_string(weight) << ", n = " << n;
    }
  }
}

// Coordinates so large that products overflow, or so small that they underflow, and chords that
// are not chords: no crash, no out-of-range access (the sanitizer build checks), and the pruned
// search still agrees with the plain loop.
TEST(Triangulate, ExtremeCoordinatesAndBogusForbiddenChordsAreHandled) {
  std::mt19937 rng(47);
  for (const double scale : {1e160, 1e-170, 1.0}) {
    HolePolygon polygon = random_hole(30, rng);
    for (auto& p : polygon.points) p *= scale;
    polygon.forbidden_chords = {{0, 0}, {-1, 3}, {2, 35}, {4, 5}};
    for (const auto weight : {WeightKind::MaxMin, WeightKind::Liepa, WeightKind::Area}) {
      TriangulateOptions fast{weight}, plain{weight};
      plain.prune = false;
      const auto a = triangulate_polygon(polygon, fast), b = triangulate_polygon(polygon, plain);
      ASSERT_EQ(a.has_value(), b.has_value()) << scale;
      if (!a) continue;
      EXPECT_EQ(a->triangles, b->triangles) << to_string(weight) << ", scale " << scale;
      EXPECT_TRUE(is_polygon_triangulation(30, a->triangles));
    }
  }
}

TEST(RestrictedSearch, GivesAValidTriangulationUpToThousandsOfEdges) {
  for (const int n : {7, 50, 301, 2500}) {
    std::mt19937 rng(n);
    HolePolygon polygon = random_hole(n, rng);
    for (const auto weight : {WeightKind::MaxMin, WeightKind::Liepa, WeightKind::Area}) {
      const auto result = triangulate_polygon_restricted(polygon, {weight});
      ASSERT_TRUE(result) << n;
      EXPECT_TRUE(is_polygon_triangulation(n, result->triangles)) << n << " " << to_string(weight);
      EXPECT_EQ(result->quality.degenerate, 0);
    }
  }
}

// The restricted search explores a subset of the triangulations, and the area and the smallest
// angle are exact optima of the full search: it can never beat the full search on those.
TEST(RestrictedSearch, NeverBeatsTheFullSearchOnItsExactComponents) {
  std::mt19937 rng(29);
  for (int trial = 0; trial < 12; ++trial) {
    const int n = 60 + 20 * trial;
    const HolePolygon polygon = random_hole(n, rng);
    TriangulateOptions area{WeightKind::Area}, maxmin{WeightKind::MaxMin, std::numbers::pi};
    area.restricted.above_edges = maxmin.restricted.above_edges = 0;
    const auto full_area = triangulate_polygon(polygon, area);
    const auto restricted_area = triangulate_polygon_restricted(polygon, area);
    const auto full_maxmin = triangulate_polygon(polygon, maxmin);
    const auto restricted_maxmin = triangulate_polygon_restricted(polygon, maxmin);
    ASSERT_TRUE(full_area && restricted_area && full_maxmin && restricted_maxmin);
    EXPECT_LE(full_area->quality.area, restricted_area->quality.area * (1.0 + 1e-12));
    EXPECT_GE(full_maxmin->quality.min_angle,
              restricted_maxmin->quality.min_angle - kAngleResolution);
  }
}

TEST(RestrictedSearch, LargeHolesUseItAndSmallOnesDoNot) {
  std::mt19937 rng(31);
  const HolePolygon polygon = random_hole(120, rng);
  TriangulateOptions options{WeightKind::Liepa};
  options.restricted.above_edges = 100;  // 120 edges: restricted
  // A random polygon folds in places whatever the chords; the fallback to the full search on a
  // fold is tests/robust/large_hole_test.cpp's.
  options.restricted.full_search_above_dihedral = std::numbers::pi;
  const auto through_threshold = triangulate_polygon(polygon, options);
  const auto restricted = triangulate_polygon_restricted(polygon, options);
  ASSERT_TRUE(through_threshold && restricted);
  EXPECT_EQ(through_threshold->triangles, restricted->triangles);
  options.restricted.above_edges = 0;  // never
  options.prune = false;
  const auto full = triangulate_polygon(polygon, options);
  options.prune = true;
  EXPECT_EQ(triangulate_polygon(polygon, options)->triangles, full->triangles);
}

TEST(RestrictedSearch, RespectsForbiddenChords) {
  std::mt19937 rng(37);
  const int n = 400;
  HolePolygon polygon = random_hole(n, rng);
  polygon.forbidden_chords = random_forbidden_chords(n, rng);
  const std::set<std::pair<int, int>> forbidden(polygon.forbidden_chords.begin(),
                                                polygon.forbidden_chords.end());
  const auto result = triangulate_polygon_restricted(polygon, {WeightKind::MaxMin});
  if (!result) GTEST_SKIP() << "no allowed triangulation; the caller falls back to the full search";
  for (const auto& t : result->triangles) {
    EXPECT_FALSE(forbidden.count({t[0], t[1]}) || forbidden.count({t[1], t[2]}) ||
                 forbidden.count({t[0], t[2]}));
  }
}

TEST(Triangulate, NeverUsesAForbiddenChord) {
  std::mt19937 rng(13);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 6 + trial % 20;
    HolePolygon polygon = random_hole(n, rng);
    polygon.forbidden_chords = random_forbidden_chords(n, rng);
    const std::set<std::pair<int, int>> forbidden(polygon.forbidden_chords.begin(),
                                                  polygon.forbidden_chords.end());
    for (const auto weight : {WeightKind::MaxMin, WeightKind::Liepa, WeightKind::Area}) {
      const auto dp = triangulate_polygon(polygon, {weight});
      if (!dp) continue;
      EXPECT_EQ(dp->triangles.size(), static_cast<std::size_t>(n - 2));
      for (const auto& t : dp->triangles) {
        EXPECT_FALSE(forbidden.count({t[0], t[1]}) || forbidden.count({t[1], t[2]}) ||
                     forbidden.count({t[0], t[2]}));
      }
    }
  }
}

TEST(Triangulate, ReportsNoTriangulationWhenEveryChordIsForbidden) {
  std::mt19937 rng(17);
  HolePolygon polygon = random_hole(6, rng);
  for (int i = 0; i < 6; ++i) {
    for (int k = i + 2; k < 6; ++k) {
      if (!(i == 0 && k == 5)) polygon.forbidden_chords.emplace_back(i, k);
    }
  }
  EXPECT_FALSE(triangulate_polygon(polygon, {WeightKind::MaxMin}).has_value());
  EXPECT_FALSE(triangulate_polygon(polygon, {WeightKind::Area}).has_value());
}

TEST(Triangulate, CollinearPointsGiveFiniteWeightsAndAreAvoided) {
  HolePolygon polygon;
  // A square with an extra point in the middle of one side: one triangle could be flat.
  polygon.points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  polygon.outside_normals.assign(5, Point(0, 0, 1));
  for (const auto weight : {WeightKind::MaxMin, WeightKind::Liepa, WeightKind::Area}) {
    const auto dp = triangulate_polygon(polygon, {weight});
    ASSERT_TRUE(dp);
    EXPECT_EQ(dp->quality.degenerate, 0) << to_string(weight);
    EXPECT_TRUE(std::isfinite(dp->quality.min_angle) && std::isfinite(dp->quality.max_dihedral));
  }
  const geometry::TriangleMeasures flat =
      geometry::measure_triangle({0, 0, 0}, {1, 0, 0}, {2, 0, 0});
  EXPECT_TRUE(flat.degenerate);
  EXPECT_EQ(flat.min_angle, 0.0);
}

TEST(Triangulate, MeasureTriangleGivesTheSmallestAngle) {
  // A 30-60-90 triangle.
  const auto m = geometry::measure_triangle({0, 0, 0}, {std::sqrt(3.0), 0, 0}, {0, 1, 0});
  EXPECT_NEAR(m.min_angle, std::numbers::pi / 6.0, 1e-12);
  EXPECT_NEAR(m.area, std::sqrt(3.0) / 2.0, 1e-12);
  EXPECT_FALSE(m.degenerate);
}

}  // namespace
}  // namespace holefill
