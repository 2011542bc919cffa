// The restricted search for large holes: the same dynamic program over a sparse set of chords
// instead of all O(n^2), so a hole of thousands of edges takes a fraction of a second.
//
// Allowed chords: every chord inside a "pocket" of consecutive boundary vertices (pockets overlap
// by half), every chord between "anchors" (every half-pocket-th vertex), and chords to each
// vertex's nearest boundary neighbours in space. A valid triangulation always exists in this set
// (triangulate the anchors' polygon with anchor chords, then each stretch between two anchors
// inside its pocket), unless chords that already exist in the mesh forbid it; then the caller
// falls back to the full search.
#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>

#include "dp_step.h"
#include "holefill/triangulate.h"

namespace holefill {
namespace {

std::uint64_t chord_key(int i, int k) {
  return (static_cast<std::uint64_t>(i) << 32) | static_cast<std::uint32_t>(k);
}

struct ChordSet {
  std::vector<std::pair<int, int>> chords;  // (i, k), i < k, k - i >= 2, plus (0, n-1)
  std::unordered_set<std::uint64_t> keys;
  void add(int a, int b) {
    if (a > b) std::swap(a, b);
    if (b - a < 2 || !keys.insert(chord_key(a, b)).second) return;
    chords.emplace_back(a, b);
  }
};

ChordSet allowed_chords(const HolePolygon& polygon, const RestrictedSearch& search) {
  const int n = static_cast<int>(polygon.points.size());
  const int pocket = std::max(4, std::min(search.pocket_edges, n));
  const int step = std::max(2, pocket / 2);
  ChordSet set;
  for (int start = 0; start < n; start += step) {
    for (int a = 0; a <= pocket; ++a) {
      for (int b = a + 2; b <= pocket; ++b) set.add((start + a) % n, (start + b) % n);
    }
  }
  std::vector<int> anchors;
  for (int a = 0; a < n; a += step) anchors.push_back(a);
  if (anchors.back() != n - 1) anchors.push_back(n - 1);
  for (std::size_t a = 0; a < anchors.size(); ++a) {
    for (std::size_t b = a + 1; b < anchors.size(); ++b) set.add(anchors[a], anchors[b]);
  }
  const auto& p = polygon.points;
  std::vector<std::pair<double, int>> by_distance;
  for (int i = 0; i < n; ++i) {
    by_distance.clear();
    for (int j = 0; j < n; ++j) {
      if (j != i) by_distance.emplace_back((p[i] - p[j]).sqrnorm(), j);
    }
    const int nearest =
        std::min<int>(search.nearest_neighbours, static_cast<int>(by_distance.size()));
    std::partial_sort(by_distance.begin(), by_distance.begin() + nearest, by_distance.end());
    for (int r = 0; r < nearest; ++r) set.add(i, by_distance[r].second);
  }
  set.add(0, n - 1);  // the whole polygon, the root cell
  return set;
}

template <class Weight>
std::optional<PolygonTriangulation> solve_restricted(const HolePolygon& polygon,
                                                     const Weight& weight,
                                                     const RestrictedSearch& search) {
  const auto& p = polygon.points;
  const int n = static_cast<int>(p.size());
  ChordSet set = allowed_chords(polygon, search);
  std::unordered_set<std::uint64_t> forbidden;
  for (const auto& [a, b] : polygon.forbidden_chords) {
    forbidden.insert(chord_key(std::min(a, b), std::max(a, b)));
  }
  auto& chords = set.chords;
  chords.erase(std::remove_if(chords.begin(), chords.end(),
                              [&](const std::pair<int, int>& c) {
                                return !(c.first == 0 && c.second == n - 1) &&
                                       forbidden.count(chord_key(c.first, c.second));
                              }),
               chords.end());
  // Shorter sub-polygons first: a cell needs the cells of its two sides.
  std::sort(chords.begin(), chords.end(), [](const auto& a, const auto& b) {
    return a.second - a.first != b.second - b.first ? a.second - a.first < b.second - b.first
                                                    : a.first < b.first;
  });
  std::unordered_map<std::uint64_t, int> cell_of;
  cell_of.reserve(chords.size() * 2);
  for (std::size_t c = 0; c < chords.size(); ++c) {
    cell_of[chord_key(chords[c].first, chords[c].second)] = static_cast<int>(c);
  }
  // up[i]: vertices m > i joined to i by a polygon edge or an allowed chord, ascending.
  std::vector<std::vector<int>> up(n);
  for (int i = 0; i + 1 < n; ++i) up[i].push_back(i + 1);
  for (const auto& [a, b] : chords) up[a].push_back(b);
  for (auto& list : up) std::sort(list.begin(), list.end());

  std::vector<WeightValue> values(chords.size());
  std::vector<int> apexes(chords.size(), -1);
  const WeightValue edge_value{};
  // The cell of side (a, b): -1 for a polygon edge, -2 when the side is not allowed or unsolved.
  auto side = [&](int a, int b) {
    if (b == a + 1) return -1;
    const auto found = cell_of.find(chord_key(a, b));
    return found == cell_of.end() || apexes[found->second] < 0 ? -2 : found->second;
  };
  auto normal_across = [&](int a, int b) -> Point {
    const int cell = side(a, b);
    if (cell == -1) return polygon.outside_normals[a];
    return detail::unit_normal(p[a], p[apexes[cell]], p[b]);
  };
  for (std::size_t c = 0; c < chords.size(); ++c) {
    const auto [i, k] = chords[c];
    detail::CellBest best;
    for (const int m : up[i]) {
      if (m >= k) break;
      const int left = side(i, m), right = side(m, k);
      if (left == -2 || right == -2) continue;
      const WeightValue& right_value = right < 0 ? edge_value : values[right];
      detail::try_apex<true>(weight, polygon, i, m, k, left < 0 ? edge_value : values[left],
                             {right_value.key, right_value.area, &right_value.area}, normal_across,
                             best);
    }
    values[c] = best.value;
    apexes[c] = best.apex;
  }
  if (side(0, n - 1) < 0) return std::nullopt;

  PolygonTriangulation result;
  result.triangles =
      detail::trace_triangles(n, [&](int i, int k) { return apexes[cell_of.at(chord_key(i, k))]; });
  result.quality = evaluate_triangulation(polygon, result.triangles);
  return result;
}

}  // namespace

std::optional<PolygonTriangulation> triangulate_polygon_restricted(
    const HolePolygon& polygon, const TriangulateOptions& options) {
  if (polygon.points.size() < 3 || polygon.points.size() >= kMaxPolygonSize) return std::nullopt;
  if (!detail::is_canonical(polygon)) {
    return triangulate_polygon_restricted(detail::canonical(polygon), options);
  }
  return detail::with_weight(options, [&](const auto& weight) {
    return solve_restricted(polygon, weight, options.restricted);
  });
}

}  // namespace holefill
