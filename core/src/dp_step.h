// One step of the triangulation dynamic program, shared by the full search (triangulate.cpp) and
// the restricted one (triangulate_restricted.cpp): try apex m for cell (i, k) and keep it when it
// beats the cell's best so far.
#pragma once

#include <cmath>

#include "holefill/triangulate.h"

namespace holefill::detail {

inline Point unit_normal(const Point& a, const Point& b, const Point& c) {
  Point n = OpenMesh::cross(b - a, c - a);
  const double length = n.norm();
  return length > 0.0 ? n / length : Point(0.0, 0.0, 0.0);
}

inline bool is_zero(const Point& p) { return p[0] == 0.0 && p[1] == 0.0 && p[2] == 0.0; }

// Dihedral angle against what lies across an edge; nothing known there (zero) adds nothing.
inline double dihedral_against(const Point& normal, const Point& other) {
  return is_zero(other) ? 0.0 : angle_between_normals(normal, other);
}

// Tries triangle (i, m, k) on top of the sub-polygon values `left` (i..m) and `right` (m..k).
// normal_across(a, b) gives the normal of the triangle chosen for sub-polygon (a, b), or of the
// mesh face across (a, b) when that is an edge of the polygon. With `prune`, candidates are
// dropped as soon as a partial value fails to beat the best: adding a triangle only worsens every
// component of a weight, so this never drops a candidate the plain loop would keep.
template <class Weight, class NormalAcross>
void try_apex(const Weight& weight, const HolePolygon& polygon, int i, int m, int k,
              const typename Weight::Value& left, const typename Weight::Value& right,
              const NormalAcross& normal_across, bool prune, typename Weight::Value& best,
              int& best_apex) {
  const auto& p = polygon.points;
  const int n = static_cast<int>(p.size());
  const bool have_best = best_apex >= 0;
  const bool pruning = prune && have_best;
  typename Weight::Value value = Weight::combine(left, right);
  if (pruning && !weight.less(value, best)) return;
  if (pruning) {
    // The triangle's area costs one cross product: at its best (no defect, no angle or
    // dihedral penalty), does the candidate still beat the best?
    TriangleMeasures optimistic;
    optimistic.area = 0.5 * OpenMesh::cross(p[m] - p[i], p[k] - p[i]).norm();
    optimistic.min_angle = M_PI;
    if (!weight.less(Weight::combine(value, weight.of(optimistic)), best)) return;
  }
  TriangleMeasures measures = measure_triangle(p[i], p[m], p[k], Weight::kUsesMinAngle);
  if constexpr (Weight::kUsesDihedral) {
    if (pruning && !weight.less(Weight::combine(value, weight.of(measures)), best)) return;
    const Point normal = unit_normal(p[i], p[m], p[k]);
    double worst = std::max(dihedral_against(normal, normal_across(i, m)),
                            dihedral_against(normal, normal_across(m, k)));
    if (i == 0 && k == n - 1) {
      worst = std::max(worst, dihedral_against(normal, polygon.outside_normals[n - 1]));
    }
    measures.max_dihedral = worst;
  }
  value = Weight::combine(value, weight.of(measures));
  if (!have_best || weight.less(value, best)) {
    best = value;
    best_apex = m;
  }
}

// Calls solve(weight) with the weight policy options.weight names (weights.h).
template <class Solve>
auto with_weight(const TriangulateOptions& options, Solve&& solve) {
  switch (options.weight) {
    case WeightKind::Liepa:
      return solve(LiepaWeight{options.angle_tolerance});
    case WeightKind::Area:
      return solve(AreaWeight{});
    case WeightKind::MaxMin:
      break;
  }
  return solve(MaxMinWeight{options.angle_tolerance, options.fold_limit});
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
