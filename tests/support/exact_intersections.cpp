#include "exact_intersections.h"

#include <algorithm>

#include "exact_triangle_intersection.h"

namespace holefill::testing {

bool exactly_intersect(const std::array<Point, 3>& a, const std::array<Point, 3>& b) {
  return detail::exactly_intersect(a, b);
}

std::size_t exact_patch_intersections(const Mesh& mesh, const std::vector<FaceHandle>& patch) {
  auto corners = [&](FaceHandle f) {
    std::array<Point, 3> c;
    int i = 0;
    for (const auto v : mesh.fv_range(f)) c[i++ % 3] = mesh.point(v);
    return c;
  };
  auto apart = [](const std::array<Point, 3>& a, const std::array<Point, 3>& b) {
    for (int axis = 0; axis < 3; ++axis) {
      const auto [a0, a1] = std::minmax({a[0][axis], a[1][axis], a[2][axis]});
      const auto [b0, b1] = std::minmax({b[0][axis], b[1][axis], b[2][axis]});
      if (a1 < b0 || b1 < a0) return true;
    }
    return false;
  };
  std::vector<int> position(mesh.n_faces(), -1);
  for (std::size_t i = 0; i < patch.size(); ++i) position[patch[i].idx()] = static_cast<int>(i);
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < patch.size(); ++i) {
    const auto a = corners(patch[i]);
    for (const auto f : mesh.faces()) {
      // Pairs within the patch once, from their first face.
      if (position[f.idx()] >= 0 && position[f.idx()] <= static_cast<int>(i)) continue;
      const auto b = corners(f);
      if (!apart(a, b) && detail::exactly_intersect(a, b)) ++pairs;
    }
  }
  return pairs;
}

}  // namespace holefill::testing
