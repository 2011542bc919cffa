#include "safe_scale.h"

#include <cmath>

namespace holefill::detail {
namespace {

Point times_power_of_two(const Point& p, int exponent) {
  return Point(std::ldexp(p[0], exponent), std::ldexp(p[1], exponent), std::ldexp(p[2], exponent));
}

}  // namespace

double SafeScale::largest_coordinate(const Point& point) {
  double largest = 0.0;
  for (int axis = 0; axis < 3; ++axis) largest = std::max(largest, std::abs(point[axis]));
  return largest;
}

double SafeScale::largest_coordinate(const Mesh& mesh) {
  double largest = 0.0;
  for (const auto v : mesh.vertices())
    largest = std::max(largest, largest_coordinate(mesh.point(v)));
  return largest;
}

bool SafeScale::leaves_alone(double largest) {
  return !(largest > 0.0) || !std::isfinite(largest) ||
         std::abs(std::ilogb(largest)) <= kMaxExponent;
}

SafeScale::SafeScale(Mesh& mesh) : mesh_(mesh) {
  const double largest = largest_coordinate(mesh);
  if (leaves_alone(largest)) return;
  exponent_ = std::ilogb(largest);
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
