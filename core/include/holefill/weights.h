// The three triangulation weights of the paper (Sec. II, Step 1), with the paper's order
// ("smaller is better") and addition, so that the dynamic program is written once.
//   area   (Barequet & Sharir 1995): total area.
//   liepa  (Liepa 2003): (largest dihedral angle, total area), lexicographic.
//   maxmin (Wei, Wu & Pang 2010): (smallest interior angle, largest dihedral angle, total area):
//          a larger smallest angle is better, then a smaller dihedral, then a smaller area.
// Every weight puts the number of degenerate triangles first (kDegenerateSine: a smallest angle
// under about 1e-10 rad, whatever the triangle's size; zero-area and NaN triangles among them),
// so that a degenerate candidate is the worst choice under any weight, never a NaN and never a
// "free" zero area.
// maxmin then compares how far the largest dihedral angle exceeds a limit (45 degrees by
// default): the smallest angle alone happily folds a patch over itself on a curved hole, or cuts
// across a tube, so a triangulation that stays under the limit always wins, and among those that
// cannot the one bending least. Under the limit the paper's order decides; a limit of pi
// reproduces it exactly. (Measured by the project's quality benchmark, holefill-quality: 45
// degrees halves the distance to the truth on a torus hole against 90, with the same triangle
// angles.)
//
// A weight's value is one 64-bit key (the degenerate count, then up to three quantised angle
// terms, compared as an integer) and the area; how the key's bits are laid out is the library's
// own business (only the order of WeightValues is promised).
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

namespace holefill {

enum class WeightKind { MaxMin, Liepa, Area };

std::string to_string(WeightKind kind);
// Parses "maxmin", "liepa" or "area"; returns false for anything else.
bool parse_weight(const std::string& text, WeightKind& kind);

inline constexpr double kDefaultFoldLimit = std::numbers::pi / 4.0;

// A triangle is degenerate when twice its area is at most kDegenerateSine times its longest edge
// squared: the sine of its smallest angle, up to a factor of at most 2, is below about 1e-10.
inline constexpr double kDegenerateSine = 1e-10;

// The largest angle difference that quantisation can tie, radians, for the smallest angle and for
// dihedral angles below 90 degrees. A weight's leading angle term (liepa's largest dihedral,
// maxmin's smallest angle under a fold limit of pi) is optimal up to this; later terms are
// optimised only among the sub-polygons' best values, as in any bottleneck DP of this kind.
inline constexpr double kAngleResolution = 4.5e-5;

// A weight's value: smaller is better.
struct WeightValue {
  std::uint64_t key = 0;
  double area = 0.0;
};
inline bool operator<(const WeightValue& a, const WeightValue& b) {
  return a.key != b.key ? a.key < b.key : a.area < b.area;
}
inline bool operator==(const WeightValue& a, const WeightValue& b) {
  return a.key == b.key && a.area == b.area;
}

}  // namespace holefill
