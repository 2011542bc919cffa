#include "delaunay_swap.h"

#include <cmath>
#include <numbers>

#include "geometry.h"

namespace holefill::detail {
namespace {

// What the cotangents of the angles at c and d opposite edge a-b tell without atan2.
enum class QuickVerdict { Keep, Swap, AskTheAngles };

// For angles alpha, beta in (0, pi): sin(alpha + beta) = (cot alpha + cot beta) sin alpha sin beta,
// so alpha + beta <= pi exactly when cot alpha + cot beta >= 0, and beyond pi by delta where
// sin delta = -(cot alpha + cot beta) sin alpha sin beta. Keep: the sum is clearly at most pi.
// Swap: both cotangents below 100 in size (sines above 1/101) and their sum below -0.01, so the
// angles exceed pi by more than 0.01 / 101^2 ~ 1e-6; the swapped edge's opposite angles sum to at
// most 2 pi minus theirs (a quadrilateral's angles, skew or not, sum to at most 2 pi), so the
// exact test's two comparisons both hold by 1e-6, far beyond its 1e-9 margin and any rounding.
// Everything closer (or degenerate) goes to the exact test.
QuickVerdict quick_verdict(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Point ca = a - c, cb = b - c, da = a - d, db = b - d;
  const double sin_c = OpenMesh::cross(ca, cb).norm(), sin_d = OpenMesh::cross(da, db).norm();
  if (!(sin_c > 0.0 && sin_d > 0.0)) return QuickVerdict::AskTheAngles;
  const double cot_c = OpenMesh::dot(ca, cb) / sin_c, cot_d = OpenMesh::dot(da, db) / sin_d;
  if (cot_c + cot_d > 1e-6 * (std::abs(cot_c) + std::abs(cot_d) + 1.0)) return QuickVerdict::Keep;
  if (cot_c + cot_d < -0.01 && std::abs(cot_c) < 100.0 && std::abs(cot_d) < 100.0) {
    return QuickVerdict::Swap;
  }
  return QuickVerdict::AskTheAngles;
}

}  // namespace

bool should_swap_quad(const Point& a, const Point& b, const Point& c, const Point& d) {
  const QuickVerdict quick = quick_verdict(a, b, c, d);  // most edges: no atan2 needed
  if (quick != QuickVerdict::AskTheAngles) return quick == QuickVerdict::Swap;
  const double opposite_now = geometry::angle_at(c, a, b) + geometry::angle_at(d, a, b);
  const double opposite_swapped = geometry::angle_at(a, c, d) + geometry::angle_at(b, c, d);
  // On a curved patch both diagonals of a quad can see more than pi; swapping only when it lowers
  // the opposite-angle sum keeps relaxation from swapping an edge back and forth. The margin
  // keeps co-circular configurations still.
  constexpr double kMargin = 1e-9;
  return opposite_now > std::numbers::pi + kMargin && opposite_swapped < opposite_now - kMargin;
}

}  // namespace holefill::detail
