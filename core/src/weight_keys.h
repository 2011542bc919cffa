// How a weight's value is packed into one 64-bit key (weights.h), and the three weights' rules
// for filling it, for the dynamic program's inner loop (triangulate.cpp, full_search.cpp).
//
// A weight's value is one 64-bit key and the area. The key packs four 16-bit lanes, most
// significant first: the degenerate count (added), then up to three angle terms (combined by
// max), each quantised so that a larger lane is worse. Comparing keys as integers then is the
// lexicographic order, and the larger of two keys is a lower bound of their combination, which
// lets the dynamic program discard most candidates with one integer compare. Angles are
// quantised through cheap monotone stand-ins (no atan2): the smallest angle through its tangent,
// a dihedral angle through the chord |n1 - n2| = 2 sin(angle / 2) between unit normals.
// Quantisation makes angles within one step (kAngleResolution) tie, so the paper's tie-breaks
// take effect despite rounding, and, unlike a tolerance, it is a true order (transitive).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#if defined(__SSE2__) && defined(__x86_64__)
#include <emmintrin.h>
#endif

#include "holefill/weights.h"

namespace holefill::detail {

namespace weight_key {

inline constexpr std::uint64_t kLaneMax = 0xFFFF;
// The key of a cell with no valid triangulation: above every real key (the degenerate count of a
// real one is below kLaneMax, since polygons have fewer than 0xFFFF points).
inline constexpr std::uint64_t kInfeasible = ~std::uint64_t{0};
inline constexpr int kDegenerateShift = 48;
inline constexpr int kLaneA = 32, kLaneB = 16, kLaneC = 0;

// x in [0, 1] to 0 ... kLaneMax; out-of-range values (and NaN) are clamped to the worst end.
inline std::uint64_t quantize_unit(double x) {
  if (!(x > 0.0)) return x == 0.0 ? 0 : kLaneMax;
  if (x >= 1.0) return kLaneMax;
  return static_cast<std::uint64_t>(x * static_cast<double>(kLaneMax) + 0.5);
}

// Smallest angle from its tangent (in (0, sqrt 3]): larger angles give smaller lanes.
inline std::uint64_t min_angle_lane(double tangent) {
  if (std::isnan(tangent)) return kLaneMax;  // unknown: the worst, not (complemented) the best
  return kLaneMax - quantize_unit(tangent * (1.0 / std::sqrt(3.0)));
}
// Dihedral angle from the chord between the two unit normals (in [0, 2]).
inline std::uint64_t dihedral_lane(double chord) { return quantize_unit(0.5 * chord); }
inline double chord_of_angle(double angle) { return 2.0 * std::sin(0.5 * angle); }

// The larger of a's and b's value in each angle lane (the degenerate lane comes out 0).
inline std::uint64_t max_angle_lanes(std::uint64_t a, std::uint64_t b) {
  constexpr std::uint64_t kAngleLanes = (std::uint64_t{1} << kDegenerateShift) - 1;
#if defined(__SSE2__) && defined(__x86_64__)
  // All three lanes at once: max(x, y) = y + (x - y, saturated at 0), lane by lane.
  const __m128i x = _mm_cvtsi64_si128(static_cast<long long>(a & kAngleLanes));
  const __m128i y = _mm_cvtsi64_si128(static_cast<long long>(b & kAngleLanes));
  return static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm_add_epi16(y, _mm_subs_epu16(x, y))));
#else
  std::uint64_t lanes = 0;
  for (const int shift : {kLaneA, kLaneB, kLaneC}) {
    lanes |= std::max((a >> shift) & kLaneMax, (b >> shift) & kLaneMax) << shift;
  }
  return lanes & kAngleLanes;
#endif
}

// The larger of a's and b's value in every lane, the degenerate count's included: a lower bound
// of their combination under every weight (counts add, angle lanes take the larger, lanes a
// weight never sets are zero in both), and at least the larger of the two keys. The dynamic
// program bounds a candidate by it: with the dihedral lane below the smallest angle's, a side's
// small angle and the other side's large dihedral combine into a key larger than either.
inline std::uint64_t lane_max(std::uint64_t a, std::uint64_t b) {
#if defined(__SSE2__) && defined(__x86_64__)
  const __m128i x = _mm_cvtsi64_si128(static_cast<long long>(a));
  const __m128i y = _mm_cvtsi64_si128(static_cast<long long>(b));
  return static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm_add_epi16(y, _mm_subs_epu16(x, y))));
#else
  std::uint64_t lanes = 0;
  for (const int shift : {kDegenerateShift, kLaneA, kLaneB, kLaneC}) {
    lanes |= std::max((a >> shift) & kLaneMax, (b >> shift) & kLaneMax) << shift;
  }
  return lanes;
#endif
}

// The combination of two keys: degenerate counts add, angle lanes take the larger. Lanes a
// weight never sets are zero, and each weight combines only its own (faster in the inner loop).
inline std::uint64_t combine(std::uint64_t a, std::uint64_t b) {
  const std::uint64_t degenerate = (a >> kDegenerateShift) + (b >> kDegenerateShift);
  return (degenerate << kDegenerateShift) | max_angle_lanes(a, b);
}
inline std::uint64_t combine_lane_a(std::uint64_t a, std::uint64_t b) {
  constexpr std::uint64_t kMask = kLaneMax << kLaneA;
  return (((a >> kDegenerateShift) + (b >> kDegenerateShift)) << kDegenerateShift) |
         std::max(a & kMask, b & kMask);
}

}  // namespace weight_key

// Each weight says which measures it needs and how a triangle's terms become lanes of its key.
struct AreaWeight {
  static constexpr bool kUsesDihedral = false;
  static constexpr bool kUsesMinAngle = false;
  static std::uint64_t combine(std::uint64_t a, std::uint64_t b) { return a + b; }  // counts only
  std::uint64_t angle_key(double /*tangent*/) const { return 0; }
  std::uint64_t dihedral_key(double /*chord*/) const { return 0; }
};

struct LiepaWeight {
  static constexpr bool kUsesDihedral = true;
  static constexpr bool kUsesMinAngle = false;
  static std::uint64_t combine(std::uint64_t a, std::uint64_t b) {
    return weight_key::combine_lane_a(a, b);
  }
  std::uint64_t angle_key(double /*tangent*/) const { return 0; }
  std::uint64_t dihedral_key(double chord) const {
    return weight_key::dihedral_lane(chord) << weight_key::kLaneA;
  }
};

struct MaxMinWeight {
  static constexpr bool kUsesDihedral = true;
  static constexpr bool kUsesMinAngle = true;
  std::uint64_t fold_lane =
      weight_key::dihedral_lane(weight_key::chord_of_angle(kDefaultFoldLimit));

  static std::uint64_t combine(std::uint64_t a, std::uint64_t b) {
    return weight_key::combine(a, b);
  }
  static MaxMinWeight with_fold_limit(double fold_limit) {
    MaxMinWeight weight;
    weight.fold_lane = weight_key::dihedral_lane(
        weight_key::chord_of_angle(std::clamp(fold_limit, 0.0, std::numbers::pi)));
    return weight;
  }
  std::uint64_t angle_key(double tangent) const {
    return weight_key::min_angle_lane(tangent) << weight_key::kLaneB;
  }
  // Lane A: how far the dihedral exceeds the fold limit; lane C: the dihedral itself.
  std::uint64_t dihedral_key(double chord) const {
    const std::uint64_t lane = weight_key::dihedral_lane(chord);
    return ((std::max(lane, fold_lane) - fold_lane) << weight_key::kLaneA) |
           (lane << weight_key::kLaneC);
  }
};

}  // namespace holefill::detail
