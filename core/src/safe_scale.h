// Meshes at any finite scale: the stages compute squared lengths and norms of cross
// products, which overflow beyond coordinates of about 1e77 and underflow below about 1e-77
// (an octahedron at 8.5e153 once crashed the intersection check; at 1e200 every triangle looked
// degenerate). A mesh whose largest coordinate lies outside [2^-kMaxExponent, 2^kMaxExponent] is
// scaled by a power of two for the fill and scaled back after, and the original vertices are
// then put back bit for bit (scaling a number near the smallest doubles could round it).
#pragma once

#include <vector>

#include "holefill/mesh.h"

namespace holefill::detail {

class SafeScale {
 public:
  static constexpr int kMaxExponent = 200;

  // Scales `mesh` (when needed) so that its largest coordinate lies in [1, 2).
  explicit SafeScale(Mesh& mesh);

  // The largest absolute coordinate of the mesh's vertices or of one point (NaN ignored).
  static double largest_coordinate(const Mesh& mesh);
  static double largest_coordinate(const Point& point);
  // Whether a mesh whose largest absolute coordinate is `largest` is left as it is.
  static bool leaves_alone(double largest);
  // Scales the vertices added since back and restores the original ones exactly.
  ~SafeScale();
  SafeScale(const SafeScale&) = delete;
  SafeScale& operator=(const SafeScale&) = delete;

  bool scaled() const { return !original_.empty(); }

 private:
  Mesh& mesh_;
  int exponent_ = 0;             // the mesh was multiplied by 2^-exponent_
  std::vector<Point> original_;  // positions of the vertices there were, when scaled
};

}  // namespace holefill::detail
