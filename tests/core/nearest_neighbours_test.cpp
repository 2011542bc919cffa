// The restricted search's nearest neighbours from the k-d tree against sorting every distance:
// the chords it allows, and so the triangulation it finds, must not change.
#include "nearest_neighbours.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace holefill {
namespace {

std::vector<std::vector<int>> by_sorting_every_distance(const std::vector<Point>& points,
                                                        int count) {
  std::vector<std::vector<int>> result(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::vector<std::pair<double, int>> all;
    for (std::size_t j = 0; j < points.size(); ++j) {
      if (j != i) all.emplace_back((points[i] - points[j]).sqrnorm(), static_cast<int>(j));
    }
    std::sort(all.begin(), all.end());
    for (int r = 0; r < std::min<int>(count, static_cast<int>(all.size())); ++r) {
      result[i].push_back(all[r].second);
    }
  }
  return result;
}

std::vector<std::vector<Point>> point_sets() {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::vector<std::vector<Point>> sets;
  for (const int n : {1, 2, 17, 300}) {
    std::vector<Point> random;
    for (int i = 0; i < n; ++i) {
      random.emplace_back(coordinate(rng), coordinate(rng), 0.1 * coordinate(rng));
    }
    sets.push_back(random);
  }
  // Ties everywhere: a regular polygon, an integer grid, and repeated points.
  std::vector<Point> regular, grid, repeated;
  for (int i = 0; i < 64; ++i) {
    regular.emplace_back(std::cos(2.0 * std::numbers::pi * i / 64),
                         std::sin(2.0 * std::numbers::pi * i / 64), 0.0);
    grid.emplace_back(i % 8, i / 8, 0.0);
    repeated.emplace_back(i % 5, 0.0, 0.0);
  }
  sets.insert(sets.end(), {regular, grid, repeated});
  // Squared distances that overflow, or underflow to zero.
  for (const double scale : {1e160, 1e-170}) {
    std::vector<Point> scaled = sets[2];
    for (auto& p : scaled) p *= scale;
    sets.push_back(scaled);
  }
  return sets;
}

TEST(NearestNeighbours, MatchSortingEveryDistanceIncludingTies) {
  for (const auto& points : point_sets()) {
    for (const int count : {0, 1, 4, 16, 500}) {
      EXPECT_EQ(detail::nearest_neighbours(points, count), by_sorting_every_distance(points, count))
          << points.size() << " points, " << count << " neighbours";
    }
  }
}

}  // namespace
}  // namespace holefill
