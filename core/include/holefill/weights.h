// The three triangulation weights of the paper (Sec. II, Step 1), as small value types with the
// paper's order ("smaller is better") and addition, so that the dynamic program is written once.
//   area   (Barequet & Sharir 1995): total area.
//   liepa  (Liepa 2003): (largest dihedral angle, total area), lexicographic.
//   maxmin (Wei, Wu & Pang 2010): (smallest interior angle, largest dihedral angle, total area):
//          a larger smallest angle is better, then a smaller dihedral, then a smaller area.
// Every weight puts the number of degenerate (zero-area) triangles first, so that a degenerate
// candidate is the worst choice under any weight, never a NaN and never a "free" zero area.
// maxmin then compares how far the largest dihedral angle exceeds a limit (45 degrees by
// default): the smallest angle alone happily folds a patch over itself on a curved hole, or cuts
// across a tube, so a triangulation that stays under the limit always wins, and among those that
// cannot the one bending least. Under the limit the paper's order decides; a limit of pi
// reproduces it exactly. (bench/quality: 45 degrees halves the distance to the truth on a torus
// hole against 90, with the same triangle angles.)
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace holefill {

enum class WeightKind { MaxMin, Liepa, Area };

std::string to_string(WeightKind kind);
// Parses "maxmin", "liepa" or "area"; returns false for anything else.
bool parse_weight(const std::string& text, WeightKind& kind);

// What the weights measure on one candidate triangle of the dynamic program.
struct TriangleMeasures {
  double min_angle = 0.0;     // radians, the triangle's smallest interior angle
  double max_dihedral = 0.0;  // radians, largest angle between its normal and its neighbours'
  double area = 0.0;
  bool degenerate = false;
};

// Angles closer than this (radians) compare as equal, so that the paper's tie-breaks (dihedral,
// then area) take effect despite floating-point noise in angles that are equal in exact terms.
inline constexpr double kDefaultAngleTolerance = 1e-9;
inline constexpr double kDefaultFoldLimit = M_PI / 4.0;

struct AreaWeight {
  static constexpr bool kUsesDihedral = false;
  static constexpr bool kUsesMinAngle = false;
  struct Value {
    int degenerate = 0;
    double area = 0.0;
  };
  static Value identity() { return {}; }
  static Value of(const TriangleMeasures& t) { return {t.degenerate ? 1 : 0, t.area}; }
  static Value combine(const Value& a, const Value& b) {
    return {a.degenerate + b.degenerate, a.area + b.area};
  }
  bool less(const Value& a, const Value& b) const {
    if (a.degenerate != b.degenerate) return a.degenerate < b.degenerate;
    return a.area < b.area;
  }
};

struct LiepaWeight {
  static constexpr bool kUsesDihedral = true;
  static constexpr bool kUsesMinAngle = false;
  double angle_tolerance = kDefaultAngleTolerance;
  struct Value {
    int degenerate = 0;
    double max_dihedral = 0.0;
    double area = 0.0;
  };
  static Value identity() { return {}; }
  static Value of(const TriangleMeasures& t) {
    return {t.degenerate ? 1 : 0, t.max_dihedral, t.area};
  }
  static Value combine(const Value& a, const Value& b) {
    return {a.degenerate + b.degenerate, std::max(a.max_dihedral, b.max_dihedral), a.area + b.area};
  }
  bool less(const Value& a, const Value& b) const {
    if (a.degenerate != b.degenerate) return a.degenerate < b.degenerate;
    if (std::abs(a.max_dihedral - b.max_dihedral) > angle_tolerance) {
      return a.max_dihedral < b.max_dihedral;
    }
    return a.area < b.area;
  }
};

struct MaxMinWeight {
  static constexpr bool kUsesDihedral = true;
  static constexpr bool kUsesMinAngle = true;
  double angle_tolerance = kDefaultAngleTolerance;
  double fold_limit = kDefaultFoldLimit;
  struct Value {
    int degenerate = 0;
    double min_angle = std::numeric_limits<double>::infinity();
    double max_dihedral = 0.0;
    double area = 0.0;
  };
  static Value identity() { return {}; }
  static Value of(const TriangleMeasures& t) {
    return {t.degenerate ? 1 : 0, t.min_angle, t.max_dihedral, t.area};
  }
  static Value combine(const Value& a, const Value& b) {
    return {a.degenerate + b.degenerate, std::min(a.min_angle, b.min_angle),
            std::max(a.max_dihedral, b.max_dihedral), a.area + b.area};
  }
  bool less(const Value& a, const Value& b) const {
    if (a.degenerate != b.degenerate) return a.degenerate < b.degenerate;
    const double fold_a = std::max(0.0, a.max_dihedral - fold_limit);
    const double fold_b = std::max(0.0, b.max_dihedral - fold_limit);
    if (std::abs(fold_a - fold_b) > angle_tolerance) return fold_a < fold_b;
    if (std::abs(a.min_angle - b.min_angle) > angle_tolerance) return a.min_angle > b.min_angle;
    if (std::abs(a.max_dihedral - b.max_dihedral) > angle_tolerance) {
      return a.max_dihedral < b.max_dihedral;
    }
    return a.area < b.area;
  }
};

}  // namespace holefill
