#include "safe_scale.h"

#include <cmath>

namespace holefill::detail {
namespace {

Point times_power_of_two(const Point& p, int exponent) {
  return Point(std::ldexp(p[0], exponent), std::ldexp(p[1], exponent), std::ldexp(p[2], exponent));
}

}  // namespace

SafeScale::SafeScale(Mesh& mesh) : mesh_(mesh) {
  double largest = 0.0;
  for (const auto v : mesh.vertices()) {
    for (int axis = 0; axis < 3; ++axis) largest = std::max(largest, std::abs(mesh.point(v)[axis]));
  }
  if (!(largest > 0.0) || !std::isfinite(largest)) return;
  const int exponent = std::ilogb(largest);
  if (std::abs(exponent) <= kMaxExponent) return;
  exponent_ = exponent;
  original_.reserve(mesh.n_vertices());
  for (const auto v : mesh.vertices()) {
    original_.push_back(mesh.point(v));
    mesh.set_point(v, times_power_of_two(mesh.point(v), -exponent_));
  }
}

SafeScale::~SafeScale() {
  if (!scaled()) return;
  for (const auto v : mesh_.vertices()) {
    const auto i = static_cast<std::size_t>(v.idx());
    mesh_.set_point(
        v, i < original_.size() ? original_[i] : times_power_of_two(mesh_.point(v), exponent_));
  }
}

}  // namespace holefill::detail
