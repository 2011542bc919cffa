#include "holefill/triangulate.h"

#include <cmath>
#include <cstdint>
#include <map>

#include "dp_step.h"

namespace holefill {
namespace {

// A triangle is degenerate when its smallest angle's sine is below this (about 1e-10 rad).
constexpr double kDegenerateSine = 1e-10;

using detail::is_zero;
using detail::unit_normal;

// Triangular storage for the cells (i, k), 0 <= i < k < n: row i holds k = i+1 ... n-1.
template <class T>
class TriangularTable {
 public:
  explicit TriangularTable(int n)
      : n_(n), cells_(static_cast<std::size_t>(n) * static_cast<std::size_t>(n - 1) / 2) {}
  T& operator()(int i, int k) { return cells_[index(i, k)]; }
  const T& operator()(int i, int k) const { return cells_[index(i, k)]; }

 private:
  std::size_t index(int i, int k) const {
    const std::size_t row = static_cast<std::size_t>(i);
    return row * static_cast<std::size_t>(n_) - row * (row + 1) / 2 +
           static_cast<std::size_t>(k - i - 1);
  }
  int n_;
  std::vector<T> cells_;
};

// The same cells stored column by column: column k holds i = 0 ... k-1. The inner loop over apexes
// m reads (i, m) along a row and (m, k) down a column; a column copy keeps both reads sequential.
template <class T>
class ColumnTable {
 public:
  explicit ColumnTable(int n)
      : cells_(static_cast<std::size_t>(n) * static_cast<std::size_t>(n - 1) / 2) {}
  T& operator()(int i, int k) { return cells_[index(i, k)]; }
  const T& operator()(int i, int k) const { return cells_[index(i, k)]; }

 private:
  static std::size_t index(int i, int k) {
    const std::size_t column = static_cast<std::size_t>(k);
    return column * (column - 1) / 2 + static_cast<std::size_t>(i);
  }
  std::vector<T> cells_;
};

// The dynamic program. Candidates are skipped as soon as they cannot beat the cell's best: adding
// a triangle only makes every component of a weight worse (more degenerate triangles, a smaller
// smallest angle, a larger dihedral angle, a larger area), so a partial value that does not beat
// the best never will. Skipped candidates are exactly those the plain loop would reject, so the
// result is the same triangulation; `prune` = false runs the plain loop (for tests).
template <class Weight>
std::optional<PolygonTriangulation> solve(const HolePolygon& polygon, const Weight& weight,
                                          bool prune) {
  using Value = typename Weight::Value;
  const auto& p = polygon.points;
  const int n = static_cast<int>(p.size());
  TriangularTable<Value> values(n);
  constexpr std::uint16_t kNone = 0xFFFF;  // apex of an infeasible cell
  TriangularTable<std::uint16_t> apex(n);  // O(i,k); polygon edges get 0 (never read)
  TriangularTable<char> forbidden(n);
  for (const auto& [i, k] : polygon.forbidden_chords) {
    forbidden(std::min(i, k), std::max(i, k)) = 1;
  }
  struct ColumnCell {
    Value value;
    std::uint16_t apex;
  };
  ColumnTable<ColumnCell> by_column(n);
  for (int i = 0; i + 1 < n; ++i) {
    values(i, i + 1) = Weight::identity();
    apex(i, i + 1) = 0;
    by_column(i, i + 1) = {Weight::identity(), 0};
  }

  // Normal of the triangle chosen for sub-polygon (a, b), or of the mesh face across (a, b).
  auto normal_across = [&](int a, int b) -> Point {
    if (b == a + 1) return polygon.outside_normals[a];
    return unit_normal(p[a], p[apex(a, b)], p[b]);
  };

  // Rows from the bottom up: cell (i, k) needs (i, m) from its own row and (m, k) from below.
  for (int i = n - 3; i >= 0; --i) {
    for (int k = i + 2; k < n; ++k) {
      const bool closing_edge = (i == 0 && k == n - 1);
      if (forbidden(i, k) && !closing_edge) {
        apex(i, k) = kNone;
        by_column(i, k) = {Value{}, kNone};
        continue;
      }
      Value& best = values(i, k);
      int best_apex = -1;
      for (int m = i + 1; m < k; ++m) {
        const ColumnCell& right = by_column(m, k);
        if (apex(i, m) == kNone || right.apex == kNone) continue;
        detail::try_apex(weight, polygon, i, m, k, values(i, m), right.value, normal_across, prune,
                         best, best_apex);
      }
      apex(i, k) = best_apex < 0 ? kNone : static_cast<std::uint16_t>(best_apex);
      by_column(i, k) = {best, apex(i, k)};
    }
  }
  if (apex(0, n - 1) == kNone) return std::nullopt;

  PolygonTriangulation result;
  result.triangles = detail::trace_triangles(n, [&](int i, int k) { return apex(i, k); });
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
  const double ab = (b - a).sqrnorm(), bc = (c - b).sqrnorm(), ca = (a - c).sqrnorm();
  const double twice_area = OpenMesh::cross(b - a, c - a).norm();
  t.area = 0.5 * twice_area;
  const double longest = std::max({ab, bc, ca});
  // sin(smallest angle) >= twice_area / longest^2 (up to a factor), a scale-free test.
  t.degenerate = !(longest > 0.0) || twice_area <= kDegenerateSine * longest;
  if (t.degenerate || !with_min_angle) return t;
  // The smallest angle lies opposite the shortest edge.
  if (bc <= ab && bc <= ca) {
    t.min_angle = std::atan2(twice_area, OpenMesh::dot(b - a, c - a));
  } else if (ca <= ab) {
    t.min_angle = std::atan2(twice_area, OpenMesh::dot(a - b, c - b));
  } else {
    t.min_angle = std::atan2(twice_area, OpenMesh::dot(a - c, b - c));
  }
  return t;
}

double angle_between_normals(const Point& n1, const Point& n2) {
  if (is_zero(n1) || is_zero(n2)) return M_PI;
  return std::atan2(OpenMesh::cross(n1, n2).norm(), OpenMesh::dot(n1, n2));
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
  const std::size_t threshold = options.restricted.above_edges;
  if (threshold > 0 && polygon.points.size() > threshold) {
    if (auto restricted = triangulate_polygon_restricted(polygon, options)) return restricted;
  }
  if (polygon.points.size() > kMaxFullSearchEdges) return std::nullopt;
  return detail::with_weight(
      options, [&](const auto& weight) { return solve(polygon, weight, options.prune); });
}

}  // namespace holefill
