// One step of the triangulation dynamic program, shared by the full search (triangulate.cpp) and
// the restricted one (triangulate_restricted.cpp): try apex m for cell (i, k) and keep it when it
// beats the cell's best so far.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "bound_scan.h"
#include "geometry.h"
#include "holefill/triangulate.h"
#include "weight_keys.h"

namespace holefill::detail {

using geometry::unit_normal;

inline bool is_zero(const Point& p) { return p[0] == 0.0 && p[1] == 0.0 && p[2] == 0.0; }

// What triangle (a, b, c)'s smallest angle needs, given twice its area: whether the triangle is
// degenerate, and the dot product of the two edges at its smallest angle (the angle is
// atan2(twice_area, dot), its tangent twice_area / dot). Shared by measure_triangle and the DP.
struct SmallestAngle {
  bool degenerate = true;
  double dot = 0.0;
};
// The edges ab = b - a and ac = c - a are passed in where the caller has them already.
[[gnu::always_inline]] inline SmallestAngle smallest_angle_of_edges(const Point& ab,
                                                                    const Point& ac,
                                                                    const Point& bc,
                                                                    double twice_area) {
  const double ab2 = ab.sqrnorm(), ac2 = ac.sqrnorm(), bc2 = bc.sqrnorm();
  const double longest = std::max({ab2, ac2, bc2});
  // sin(smallest angle) >= twice_area / longest^2 (up to a factor): a scale-free test, written so
  // that NaN (coordinates whose products overflow) counts as degenerate.
  if (!(longest > 0.0) || !(twice_area > kDegenerateSine * longest)) return {};
  // The smallest angle lies opposite the shortest edge.
  const double dot = bc2 <= ab2 && bc2 <= ac2 ? OpenMesh::dot(ab, ac)
                     : ac2 <= ab2             ? -OpenMesh::dot(ab, bc)
                                              : OpenMesh::dot(ac, bc);
  return {false, dot};
}
inline SmallestAngle smallest_angle(const Point& a, const Point& b, const Point& c,
                                    double twice_area) {
  return smallest_angle_of_edges(b - a, c - a, c - b, twice_area);
}

// The chords below stand for angles only between unit normals, as HolePolygon asks, and
// forbidden triangles are looked up by binary search; these make sure of both for callers that
// pass other normals or an unsorted list (a zero normal stays zero: nothing known).
inline bool is_canonical(const HolePolygon& polygon) {
  for (const auto& normal : polygon.outside_normals) {
    const double length2 = normal.sqrnorm();
    if (length2 != 0.0 && std::abs(length2 - 1.0) > 1e-12) return false;
  }
  return std::is_sorted(polygon.forbidden_triangles.begin(), polygon.forbidden_triangles.end());
}
inline HolePolygon canonical(HolePolygon polygon) {
  for (auto& normal : polygon.outside_normals) {
    const double length = normal.norm();
    normal = length > 0.0 && length < INFINITY ? normal / length : Point(0.0, 0.0, 0.0);
  }
  std::sort(polygon.forbidden_triangles.begin(), polygon.forbidden_triangles.end());
  return polygon;
}

inline bool is_forbidden_triangle(const HolePolygon& polygon, int i, int m, int k) {
  const auto& list = polygon.forbidden_triangles;
  return !list.empty() && std::binary_search(list.begin(), list.end(), std::array<int, 3>{i, m, k});
}

// The chord |normal - other| standing for the dihedral angle against what lies across an edge,
// squared (the largest of several chords is the root of the largest square, one root for all):
// nothing known there (zero) adds nothing, no orientation of our own (zero) is the worst fold.
[[gnu::always_inline]] inline double squared_chord_against(const Point& normal,
                                                           const Point& other) {
  if (is_zero(other)) return 0.0;
  if (is_zero(normal)) return 4.0;
  return (normal - other).sqrnorm();
}

// The best apex found so far for one cell. `value` starts just below kInfeasible, so that any
// real candidate beats it and a side without a triangulation (kInfeasible) never does. Equal
// values go to the smaller apex, so the result does not depend on the order apexes are tried in.
struct CellBest {
  WeightValue value{weight_key::kInfeasible - 1, INFINITY};
  int apex = -1;
  // Whether apex m with this (partial) key and area can no longer beat the best.
  bool excludes(std::uint64_t key, double area, int m) const {
    if (key != value.key) return key > value.key;
    if (area != value.area) return !(area < value.area);
    return apex >= 0 && m > apex;
  }
};

// A sub-polygon's value as the apex loop first sees it: its key and a lower bound of its area,
// with the exact area read only for candidates that survive the cheap tests.
struct SideValue {
  std::uint64_t key = 0;
  double area_lower_bound = 0.0;
  const double* area = nullptr;
};

// The expensive part of trying triangle (i, m, k) (its smallest angle and dihedral angles), once
// the cheap tests of try_apex have passed; out of line, to keep the apex loop small.
// `to_m` and `to_k` are the edges from point i, `cross` their cross product, `twice_area` its norm.
template <bool kPrune, class Weight, class NormalAcross>
[[gnu::noinline]] void finish_apex(const Weight& weight, const HolePolygon& polygon, int i, int m,
                                   int k, std::uint64_t key, double area, const Point& to_m,
                                   const Point& to_k, const Point& cross, double twice_area,
                                   const NormalAcross& normal_across, CellBest& best) {
  if (is_forbidden_triangle(polygon, i, m, k)) return;
  const SmallestAngle angle =
      smallest_angle_of_edges(to_m, to_k, polygon.points[k] - polygon.points[m], twice_area);
  if (angle.degenerate) {
    key = weight.combine(
        key, (std::uint64_t{1} << weight_key::kDegenerateShift) | weight.angle_key(0.0));
  } else if constexpr (Weight::kUsesMinAngle) {
    // The smallest angle is acute, so its dot product is positive.
    const double tangent = angle.dot > 0.0 ? twice_area / angle.dot : std::sqrt(3.0);
    key = weight.combine(key, weight.angle_key(tangent));
  }
  if constexpr (Weight::kUsesDihedral) {
    if (kPrune && best.excludes(key, area, m)) return;
    const Point normal = twice_area > 0.0 ? cross / twice_area : Point(0.0, 0.0, 0.0);
    double squared_chord = std::max(squared_chord_against(normal, normal_across(i, m)),
                                    squared_chord_against(normal, normal_across(m, k)));
    const int n = static_cast<int>(polygon.points.size());
    if (i == 0 && k == n - 1) {
      squared_chord =
          std::max(squared_chord, squared_chord_against(normal, polygon.outside_normals[n - 1]));
    }
    key = weight.combine(key, weight.dihedral_key(std::sqrt(squared_chord)));
  }
  if (!best.excludes(key, area, m)) {
    best.value = {key, area};
    best.apex = m;
  }
}

// Tries triangle (i, m, k) on top of the sub-polygon values `left` (i..m) and `right` (m..k).
// normal_across(a, b) gives the normal of the triangle chosen for sub-polygon (a, b), or of the
// mesh face across (a, b) when that is an edge of the polygon. With kPrune, a candidate is
// dropped as soon as a partial value (or a lower bound of it) fails to beat the best: adding a
// term only makes a key larger or keeps it, and only makes the area larger, so this never drops a
// candidate the plain loop would keep, and the computed values are the same either way.
template <bool kPrune, class Weight, class NormalAcross>
[[gnu::always_inline]] inline void try_apex(const Weight& weight, const HolePolygon& polygon, int i,
                                            int m, int k, const WeightValue& left,
                                            const SideValue& right,
                                            const NormalAcross& normal_across, CellBest& best) {
  const std::uint64_t key = weight.combine(left.key, right.key);
  const double sides_lower_bound = left.area + right.area_lower_bound;
  if (kPrune && best.excludes(key, sides_lower_bound, m)) return;
  const Point& a = polygon.points[i];
  const Point to_m = polygon.points[m] - a, to_k = polygon.points[k] - a;
  const Point cross = OpenMesh::cross(to_m, to_k);
  const double squared_norm = cross.sqrnorm();
  if (kPrune && key == best.value.key &&
      squared_norm > squared_twice_room(best.value.area, sides_lower_bound)) {
    return;  // the triangle alone overfills the area left to beat the best: no root needed
  }
  // An overflowing cross product (NaN or inf) weighs as an infinite area, so areas always compare.
  const double norm = std::sqrt(squared_norm);
  const double half_area = norm < INFINITY ? 0.5 * norm : INFINITY;
  if (kPrune && best.excludes(key, sides_lower_bound + half_area, m)) return;
  const double area = (left.area + *right.area) + half_area;
  if (kPrune && best.excludes(key, area, m)) return;
  finish_apex<kPrune>(weight, polygon, i, m, k, key, area, to_m, to_k, cross, norm, normal_across,
                      best);
}

// Whether the caller has asked the search to stop (TriangulateOptions::progress).
inline bool cancelled(const TriangulateOptions& options) {
  return options.progress != nullptr && options.progress->cancelled();
}

// Calls solve(weight) with the weight policy options.weight names (weights.h).
template <class Solve>
auto with_weight(const TriangulateOptions& options, Solve&& solve) {
  switch (options.weight) {
    case WeightKind::Liepa:
      return solve(LiepaWeight{});
    case WeightKind::Area:
      return solve(AreaWeight{});
    case WeightKind::MaxMin:
      break;
  }
  return solve(MaxMinWeight::with_fold_limit(options.fold_limit));
}

// Follows the apexes from the closing edge (0, n-1) down: the triangles of the solution.
template <class ApexOf>
std::vector<std::array<int, 3>> trace_triangles(int n, const ApexOf& apex_of) {
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::pair<int, int>> pending{{0, n - 1}};
  while (!pending.empty()) {
    const auto [i, k] = pending.back();
    pending.pop_back();
    if (k - i < 2) continue;
    const int m = apex_of(i, k);
    triangles.push_back({i, m, k});
    pending.emplace_back(i, m);
    pending.emplace_back(m, k);
  }
  return triangles;
}

}  // namespace holefill::detail
