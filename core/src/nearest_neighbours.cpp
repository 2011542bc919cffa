#include "nearest_neighbours.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "point_cloud_tree.h"

namespace holefill::detail {

std::vector<std::vector<int>> nearest_neighbours(const std::vector<Point>& points, int count) {
  const std::size_t n = points.size();
  const std::size_t wanted = std::min<std::size_t>(std::max(count, 0), n > 0 ? n - 1 : 0);
  std::vector<std::vector<int>> result(n);
  if (wanted == 0) return result;
  std::vector<std::pair<double, int>> candidates;
  // Ranks candidates j of point i by (squared distance, index): what sorting all would give.
  auto choose = [&](std::size_t i, auto&& for_each_candidate) {
    candidates.clear();
    for_each_candidate([&](std::size_t j) {
      if (j != i) candidates.emplace_back((points[i] - points[j]).sqrnorm(), static_cast<int>(j));
    });
    const std::size_t take = std::min(wanted, candidates.size());
    std::partial_sort(candidates.begin(), candidates.begin() + take, candidates.end());
    for (std::size_t r = 0; r < take; ++r) result[i].push_back(candidates[r].second);
  };
  auto every_point = [n](auto&& visit) {
    for (std::size_t j = 0; j < n; ++j) visit(j);
  };
  const bool finite = std::all_of(points.begin(), points.end(), [](const Point& p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
  });
  if (!finite) {
    for (std::size_t i = 0; i < n; ++i) choose(i, every_point);
    return result;
  }
  const PointCloud cloud{points};
  PointCloudTree tree(3, cloud);
  std::vector<std::uint32_t> indices(wanted + 1);
  std::vector<double> squared(wanted + 1);
  std::vector<std::pair<std::uint32_t, double>> within;
  for (std::size_t i = 0; i < n; ++i) {
    // The tree's k nearest (the point itself among them) bound the distance of the true k-th
    // nearest; every point slightly beyond that bound is then ranked by choose(), so neither
    // rounding in the tree's pruning nor ties at the cut-off make the choice differ from
    // sorting all distances. Distances that overflow leave nothing to bound: compare all.
    const std::size_t found =
        tree.knnSearch(points[i].data(), wanted + 1, indices.data(), squared.data());
    if (found < wanted + 1 || !(squared[found - 1] < INFINITY)) {
      choose(i, every_point);
      continue;
    }
    const double radius = std::nextafter(squared[found - 1] * (1.0 + 1e-9), INFINITY);
    within.clear();
    tree.radiusSearch(points[i].data(), radius, within, nanoflann::SearchParams(0, 0.0f, false));
    choose(i, [&](auto&& visit) {
      for (const auto& candidate : within) visit(candidate.first);
    });
  }
  return result;
}

}  // namespace holefill::detail
