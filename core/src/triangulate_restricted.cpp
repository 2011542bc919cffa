// The restricted search for large holes: the same dynamic program over a sparse set of chords
// instead of all O(n^2), so a hole of thousands of edges takes a fraction of a second.
//
// Allowed chords: every chord inside a "pocket" of consecutive boundary vertices (pockets overlap
// by half), the same over "anchors" (every half-pocket-th vertex), anchors of anchors and so on,
// every chord among the few of the last level, and chords to each vertex's nearest boundary
// neighbours in space. A valid triangulation always exists in this set (triangulate the last
// level's polygon, then each stretch between two anchors inside its pocket, level by level down),
// unless forbidden chords (chords that already exist in the mesh, copies of a bridge's ends) take
// it away: then the search runs once more with the anchors moved off the ends of forbidden chords,
// and when that finds nothing either the caller falls back to the full search.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_set>

#include "dp_step.h"
#include "holefill/triangulate.h"
#include "nearest_neighbours.h"

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

// With `avoid` given, each anchor is the first vertex from every step-th one on that `avoid` does
// not mark (or that vertex when all of the step's are marked): the next anchor then still lies in
// the pocket from the last one.
ChordSet allowed_chords(const HolePolygon& polygon, const RestrictedSearch& search,
                        const std::vector<char>* avoid = nullptr) {
  const int n = static_cast<int>(polygon.points.size());
  const int pocket = std::max(4, std::min(search.pocket_edges, n));
  const int step = std::max(2, pocket / 2);
  ChordSet set;
  // Pockets of consecutive vertices, then pockets of consecutive anchors (every step-th vertex),
  // of anchors of anchors, and so on, until few enough remain to join every pair: each level can
  // triangulate the stretches between the next level's anchors, and the work stays linear in n
  // (joining every pair of anchors was cubic: 333 s at 50,000 edges).
  std::vector<int> level(n);
  std::iota(level.begin(), level.end(), 0);
  while (static_cast<int>(level.size()) > pocket + 1) {
    const int size = static_cast<int>(level.size());
    for (int start = 0; start < size; start += step) {
      for (int a = 0; a <= pocket; ++a) {
        for (int b = a + 1; b <= pocket; ++b) {
          set.add(level[(start + a) % size], level[(start + b) % size]);
        }
      }
    }
    std::vector<int> anchors;
    for (int a = 0; a < size; a += step) {
      int anchor = a;
      while (avoid && a > 0 && (*avoid)[level[anchor]] && anchor + 1 < std::min(a + step, size)) {
        ++anchor;
      }
      anchors.push_back(level[avoid && (*avoid)[level[anchor]] ? a : anchor]);
    }
    if (anchors.back() != level.back()) anchors.push_back(level.back());
    level = std::move(anchors);
  }
  for (std::size_t a = 0; a < level.size(); ++a) {
    for (std::size_t b = a + 1; b < level.size(); ++b) set.add(level[a], level[b]);
  }
  const auto neighbours = detail::nearest_neighbours(polygon.points, search.nearest_neighbours);
  for (int i = 0; i < n; ++i) {
    for (const int j : neighbours[i]) set.add(i, j);
  }
  set.add(0, n - 1);  // the whole polygon, the root cell
  return set;
}

// A cancel is noticed within this many chords (well under a millisecond).
constexpr std::size_t kChordsBetweenCancelChecks = 4096;

template <class Weight>
std::optional<PolygonTriangulation> solve_restricted(const HolePolygon& polygon,
                                                     const Weight& weight,
                                                     const TriangulateOptions& options,
                                                     const std::vector<char>* avoid) {
  const auto& p = polygon.points;
  const int n = static_cast<int>(p.size());
  ChordSet set = allowed_chords(polygon, options.restricted, avoid);
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
  // up[i]: (m, cell) for the vertices m > i joined to i by a polygon edge (cell -1) or an
  // allowed chord, ascending: sides are found by binary search (a hash map took most of the time
  // of a large hole).
  std::vector<std::vector<std::pair<int, int>>> up(n);
  for (int i = 0; i + 1 < n; ++i) up[i].emplace_back(i + 1, -1);
  for (std::size_t c = 0; c < chords.size(); ++c) {
    up[chords[c].first].emplace_back(chords[c].second, static_cast<int>(c));
  }
  for (auto& list : up) std::sort(list.begin(), list.end());
  auto cell_of = [&](int a, int b) {
    const auto& list = up[a];
    const auto found = std::lower_bound(list.begin(), list.end(), std::pair<int, int>(b, -1));
    return found != list.end() && found->first == b ? found->second : -2;
  };

  std::vector<WeightValue> values(chords.size());
  std::vector<int> apexes(chords.size(), -1);
  const WeightValue edge_value{};
  // The cell of side (a, b): -1 for a polygon edge, -2 when the side is not allowed or unsolved.
  auto side = [&](int a, int b) {
    const int cell = cell_of(a, b);
    return cell >= 0 && apexes[cell] < 0 ? -2 : cell;
  };
  auto normal_across = [&](int a, int b) -> Point {
    const int cell = side(a, b);
    if (cell == -1) return polygon.outside_normals[a];
    return detail::unit_normal(p[a], p[apexes[cell]], p[b]);
  };
  for (std::size_t c = 0; c < chords.size(); ++c) {
    if (c % kChordsBetweenCancelChecks == 0 && detail::cancelled(options)) return std::nullopt;
    const auto [i, k] = chords[c];
    detail::CellBest best;
    for (const auto& [m, left_cell] : up[i]) {
      if (m >= k) break;
      const int left = left_cell >= 0 && apexes[left_cell] < 0 ? -2 : left_cell;
      const int right = side(m, k);
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
      detail::trace_triangles(n, [&](int i, int k) { return apexes[cell_of(i, k)]; });
  result.quality = evaluate_triangulation(polygon, result.triangles);
  return result;
}

}  // namespace

std::vector<std::pair<int, int>> restricted_chords(const HolePolygon& polygon,
                                                   const RestrictedSearch& search) {
  if (polygon.points.size() < 3) return {};
  return allowed_chords(polygon, search).chords;
}

std::optional<PolygonTriangulation> triangulate_polygon_restricted(
    const HolePolygon& polygon, const TriangulateOptions& options) {
  if (polygon.points.size() < 3 || polygon.points.size() >= kMaxPolygonSize) return std::nullopt;
  if (!detail::is_canonical(polygon)) {
    return triangulate_polygon_restricted(detail::canonical(polygon), options);
  }
  return detail::with_weight(options, [&](const auto& weight) {
    auto found = solve_restricted(polygon, weight, options, nullptr);
    if (found || polygon.forbidden_chords.empty() || detail::cancelled(options)) return found;
    // An anchor at the end of a forbidden chord (a copy of a bridge's end, in loops joined by
    // bridges) can leave the levels above it without a triangulation: once more with the anchors
    // moved off such ends.
    std::vector<char> avoid(polygon.points.size(), 0);
    for (const auto& [a, b] : polygon.forbidden_chords) avoid[a] = avoid[b] = 1;
    return solve_restricted(polygon, weight, options, &avoid);
  });
}

}  // namespace holefill
