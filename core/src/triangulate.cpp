#include "holefill/triangulate.h"

#include <cmath>
#include <cstdint>
#include <map>

#include "dp_step.h"

namespace holefill {
namespace {

using detail::is_zero;
using detail::unit_normal;

// Cell (i, k), 0 <= i < k < n, of the triangular tables, stored row by row (row i holds
// k = i+1 ... n-1) or column by column (column k holds i = 0 ... k-1).
std::size_t cell_count(int n) {
  return static_cast<std::size_t>(n) * static_cast<std::size_t>(n - 1) / 2;
}
std::size_t row_start(int n, int i) {
  const std::size_t row = static_cast<std::size_t>(i);
  return row * static_cast<std::size_t>(n) - row * (row + 1) / 2;
}
std::size_t row_index(int n, int i, int k) {
  return row_start(n, i) + static_cast<std::size_t>(k - i - 1);
}
std::size_t column_start(int k) {
  const std::size_t column = static_cast<std::size_t>(k);
  return column * (column - 1) / 2;
}

// The area rounded down to a float: a lower bound that fits in half the space.
float area_lower_bound(double area) {
  const float rounded = static_cast<float>(area);
  return static_cast<double>(rounded) <= area ? rounded : std::nextafter(rounded, 0.0f);
}

// The dynamic program, in 30 bytes per cell: by rows the value (key and area) and the apex; by
// columns the key again and a lower bound of the area, so that the apex loop reads both sides
// sequentially; a bit for forbidden chords. With kPrune a candidate is skipped when the larger
// of its two sides' keys already exceeds the best key (a lower bound of its value, weights.h) or
// ties it with no smaller area, then as soon as a partial value cannot beat the best (try_apex).
// The values computed are the same either way, so the result is the plain loop's
// (kPrune = false), and tests check it.
template <bool kPrune, class Weight>
std::optional<PolygonTriangulation> solve(const HolePolygon& polygon, const Weight& weight) {
  const auto& p = polygon.points;
  const int n = static_cast<int>(p.size());
  const std::size_t cells = cell_count(n);
  std::vector<std::uint64_t> row_key(cells, 0), column_key(cells, 0);
  std::vector<double> row_area(cells, 0.0);
  std::vector<float> column_area(cells, 0.0f);
  constexpr std::uint16_t kNone = 0xFFFF;     // apex of an infeasible cell
  std::vector<std::uint16_t> apex(cells, 0);  // O(i,k); polygon edges get 0 (never read)
  std::vector<bool> forbidden(cells, false);
  for (const auto& [a, b] : polygon.forbidden_chords) {
    if (a == b || std::min(a, b) < 0 || std::max(a, b) >= n) continue;  // not a chord
    forbidden[row_index(n, std::min(a, b), std::max(a, b))] = true;
  }

  // Normals of the triangles chosen for the cells (i, m) of the current row, where the row reads
  // them over and over; normals of other cells are recomputed from their apex.
  std::vector<Point> row_normal(n);
  // Normal of the triangle chosen for sub-polygon (a, b), or of the mesh face across (a, b).
  int current_row = -1;
  auto normal_across = [&](int a, int b) -> Point {
    if (b == a + 1) return polygon.outside_normals[a];
    if (a == current_row) return row_normal[b];
    return unit_normal(p[a], p[apex[row_index(n, a, b)]], p[b]);
  };

  // Rows from the bottom up: cell (i, k) needs (i, m) from its own row and (m, k) from below.
  for (int i = n - 3; i >= 0; --i) {
    current_row = i;
    const std::size_t row = row_start(n, i);
    const std::uint64_t* left_key = row_key.data() + row;  // (i, m) at [m - i - 1]
    const double* left_area = row_area.data() + row;
    for (int k = i + 2; k < n; ++k) {
      const std::size_t cell = row + static_cast<std::size_t>(k - i - 1);
      const std::size_t column = column_start(k);
      const bool closing_edge = (i == 0 && k == n - 1);
      if (forbidden[cell] && !closing_edge) {
        row_key[cell] = column_key[column + i] = weight_key::kInfeasible;
        row_area[cell] = INFINITY;
        column_area[column + i] = INFINITY;
        apex[cell] = kNone;
        continue;
      }
      const std::uint64_t* right_key = column_key.data() + column;  // (m, k) at [m]
      const float* right_area = column_area.data() + column;
      detail::CellBest best;
      auto try_apex = [&](int m) {
        const std::uint64_t left = left_key[m - i - 1], right = right_key[m];
        if constexpr (kPrune) {
          const std::uint64_t bound = std::max(left, right);
          if (bound > best.value.key) return;
          if (bound == best.value.key &&
              best.excludes(bound, left_area[m - i - 1] + right_area[m], m)) {
            return;
          }
        } else {
          if (left == weight_key::kInfeasible || right == weight_key::kInfeasible) return;
        }
        detail::try_apex<kPrune>(
            weight, polygon, i, m, k, WeightValue{left, left_area[m - i - 1]},
            detail::SideValue{right, right_area[m], &row_area[row_index(n, m, k)]}, normal_across,
            best);
      };
      // The apex of the cell below is often this cell's best too: tried first, it lets the
      // bound discard most other apexes at once.
      const int seed = k - i > 2 ? apex[row_index(n, i + 1, k)] : kNone;
      if constexpr (kPrune) {
        if (seed != kNone) try_apex(seed);
      }
      for (int m = i + 1; m < k; ++m) {
        if (kPrune && m == seed) continue;
        try_apex(m);
      }
      const bool feasible = best.apex >= 0;
      row_key[cell] = column_key[column + i] = feasible ? best.value.key : weight_key::kInfeasible;
      row_area[cell] = best.value.area;
      column_area[column + i] = area_lower_bound(best.value.area);
      apex[cell] = feasible ? static_cast<std::uint16_t>(best.apex) : kNone;
      if (feasible) row_normal[k] = unit_normal(p[i], p[best.apex], p[k]);
    }
  }
  if (apex[row_index(n, 0, n - 1)] == kNone) return std::nullopt;

  PolygonTriangulation result;
  result.triangles =
      detail::trace_triangles(n, [&](int i, int k) { return apex[row_index(n, i, k)]; });
  result.quality = evaluate_triangulation(polygon, result.triangles);
  return result;
}

}  // namespace

std::string to_string(WeightKind kind) {
  switch (kind) {
    case WeightKind::MaxMin:
      return "maxmin";
    case WeightKind::Liepa:
      return "liepa";
    case WeightKind::Area:
      return "area";
  }
  return "?";
}

bool parse_weight(const std::string& text, WeightKind& kind) {
  for (const auto candidate : {WeightKind::MaxMin, WeightKind::Liepa, WeightKind::Area}) {
    if (text == to_string(candidate)) {
      kind = candidate;
      return true;
    }
  }
  return false;
}

TriangleMeasures measure_triangle(const Point& a, const Point& b, const Point& c,
                                  bool with_min_angle) {
  TriangleMeasures t;
  const double twice_area = OpenMesh::cross(b - a, c - a).norm();
  t.area = 0.5 * twice_area;
  const detail::SmallestAngle angle = detail::smallest_angle(a, b, c, twice_area);
  t.degenerate = angle.degenerate;
  if (!t.degenerate && with_min_angle) t.min_angle = std::atan2(twice_area, angle.dot);
  return t;
}

double angle_between_normals(const Point& n1, const Point& n2) {
  if (is_zero(n1) || is_zero(n2)) return M_PI;
  return std::atan2(OpenMesh::cross(n1, n2).norm(), OpenMesh::dot(n1, n2));
}

WeightValue weight_value(const TriangulationQuality& quality, const TriangulateOptions& options) {
  const double chord = weight_key::chord_of_angle(quality.max_dihedral);
  const std::uint64_t degenerate = static_cast<std::uint64_t>(quality.degenerate)
                                   << weight_key::kDegenerateShift;
  return detail::with_weight(options, [&](const auto& weight) {
    return WeightValue{
        weight_key::combine(degenerate,
                            weight_key::combine(weight.angle_key(std::tan(quality.min_angle)),
                                                weight.dihedral_key(chord))),
        quality.area};
  });
}

TriangulationQuality evaluate_triangulation(const HolePolygon& polygon,
                                            const std::vector<std::array<int, 3>>& triangles) {
  TriangulationQuality q;
  q.min_angle = triangles.empty() ? 0.0 : M_PI;
  const int n = static_cast<int>(polygon.points.size());
  std::map<std::pair<int, int>, Point> first_normal_on_edge;
  for (const auto& t : triangles) {
    const Point &a = polygon.points[t[0]], &b = polygon.points[t[1]], &c = polygon.points[t[2]];
    const TriangleMeasures m = measure_triangle(a, b, c);
    q.area += m.area;
    q.degenerate += m.degenerate ? 1 : 0;
    q.min_angle = std::min(q.min_angle, m.min_angle);
    const Point normal = unit_normal(a, b, c);
    for (int e = 0; e < 3; ++e) {
      const int u = std::min(t[e], t[(e + 1) % 3]), v = std::max(t[e], t[(e + 1) % 3]);
      const bool boundary_edge = (v == u + 1) || (u == 0 && v == n - 1);
      if (boundary_edge) {
        const Point& outside = polygon.outside_normals[v == u + 1 ? u : n - 1];
        if (!is_zero(outside)) {
          q.max_dihedral = std::max(q.max_dihedral, angle_between_normals(normal, outside));
        }
        continue;
      }
      const auto [it, inserted] = first_normal_on_edge.emplace(std::make_pair(u, v), normal);
      if (!inserted) {
        q.max_dihedral = std::max(q.max_dihedral, angle_between_normals(normal, it->second));
      }
    }
  }
  return q;
}

std::optional<PolygonTriangulation> triangulate_polygon(const HolePolygon& polygon,
                                                        const TriangulateOptions& options) {
  if (polygon.points.size() < 3 || polygon.points.size() >= kMaxPolygonSize) return std::nullopt;
  if (!detail::is_canonical(polygon)) {
    return triangulate_polygon(detail::canonical(polygon), options);
  }
  const std::size_t threshold = options.restricted.above_edges;
  if (threshold > 0 && polygon.points.size() > threshold) {
    if (auto restricted = triangulate_polygon_restricted(polygon, options)) return restricted;
  }
  if (polygon.points.size() > kMaxFullSearchEdges) return std::nullopt;
  return detail::with_weight(options, [&](const auto& weight) {
    return options.prune ? solve<true>(polygon, weight) : solve<false>(polygon, weight);
  });
}

}  // namespace holefill
