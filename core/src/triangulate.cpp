#include "holefill/triangulate.h"

#include <cmath>
#include <map>

namespace holefill {
namespace {

// A triangle is degenerate when its smallest angle's sine is below this (about 1e-10 rad).
constexpr double kDegenerateSine = 1e-10;

Point unit_normal(const Point& a, const Point& b, const Point& c) {
  Point n = OpenMesh::cross(b - a, c - a);
  const double length = n.norm();
  return length > 0.0 ? n / length : Point(0.0, 0.0, 0.0);
}

bool is_zero(const Point& p) { return p[0] == 0.0 && p[1] == 0.0 && p[2] == 0.0; }

// Flat storage for the (i, k) cells of the dynamic program.
template <class T>
class CellTable {
 public:
  explicit CellTable(int n) : n_(n), cells_(static_cast<std::size_t>(n) * n) {}
  T& operator()(int i, int k) { return cells_[static_cast<std::size_t>(i) * n_ + k]; }
  const T& operator()(int i, int k) const { return cells_[static_cast<std::size_t>(i) * n_ + k]; }

 private:
  int n_;
  std::vector<T> cells_;
};

template <class Weight>
std::optional<PolygonTriangulation> solve(const HolePolygon& polygon, const Weight& weight) {
  using Value = typename Weight::Value;
  struct Cell {
    Value value = Weight::identity();
    int apex = -1;  // O(i,k); -1 for an edge of the polygon or an infeasible cell
    bool feasible = false;
    Point apex_normal{0.0, 0.0, 0.0};  // normal of triangle (i, O(i,k), k)
  };
  const auto& p = polygon.points;
  const int n = static_cast<int>(p.size());
  CellTable<Cell> cells(n);
  CellTable<char> forbidden(n);
  for (const auto& [i, k] : polygon.forbidden_chords) {
    forbidden(std::min(i, k), std::max(i, k)) = 1;
  }
  for (int i = 0; i + 1 < n; ++i) cells(i, i + 1).feasible = true;

  // Dihedral angle across edge (a, b) of a candidate, against what lies on its other side.
  auto dihedral_against = [&](const Point& normal, int a, int b) {
    if (b == a + 1) {
      const Point& outside = polygon.outside_normals[a];
      return is_zero(outside) ? 0.0 : angle_between_normals(normal, outside);
    }
    return angle_between_normals(normal, cells(a, b).apex_normal);
  };

  for (int d = 2; d < n; ++d) {
    for (int i = 0; i + d < n; ++i) {
      const int k = i + d;
      const bool closing_edge = (i == 0 && k == n - 1);
      Cell& cell = cells(i, k);
      if (forbidden(i, k) && !closing_edge) continue;
      for (int m = i + 1; m < k; ++m) {
        const Cell& left = cells(i, m);
        const Cell& right = cells(m, k);
        if (!left.feasible || !right.feasible) continue;
        TriangleMeasures measures = measure_triangle(p[i], p[m], p[k]);
        Point normal(0.0, 0.0, 0.0);
        if constexpr (Weight::kUsesDihedral) {
          normal = unit_normal(p[i], p[m], p[k]);
          double dihedral =
              std::max(dihedral_against(normal, i, m), dihedral_against(normal, m, k));
          if (closing_edge && !is_zero(polygon.outside_normals[n - 1])) {
            dihedral =
                std::max(dihedral, angle_between_normals(normal, polygon.outside_normals[n - 1]));
          }
          measures.max_dihedral = dihedral;
        }
        const Value value =
            Weight::combine(Weight::combine(left.value, right.value), Weight::of(measures));
        if (!cell.feasible || weight.less(value, cell.value)) {
          cell.value = value;
          cell.apex = m;
          cell.feasible = true;
          cell.apex_normal = normal;
        }
      }
    }
  }
  if (!cells(0, n - 1).feasible) return std::nullopt;

  PolygonTriangulation result;
  std::vector<std::pair<int, int>> pending{{0, n - 1}};
  while (!pending.empty()) {
    const auto [i, k] = pending.back();
    pending.pop_back();
    if (k - i < 2) continue;
    const int m = cells(i, k).apex;
    result.triangles.push_back({i, m, k});
    pending.emplace_back(i, m);
    pending.emplace_back(m, k);
  }
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

TriangleMeasures measure_triangle(const Point& a, const Point& b, const Point& c) {
  TriangleMeasures t;
  const double ab = (b - a).sqrnorm(), bc = (c - b).sqrnorm(), ca = (a - c).sqrnorm();
  const double twice_area = OpenMesh::cross(b - a, c - a).norm();
  t.area = 0.5 * twice_area;
  const double longest = std::max({ab, bc, ca});
  // sin(smallest angle) >= twice_area / longest^2 (up to a factor), a scale-free test.
  t.degenerate = !(longest > 0.0) || twice_area <= kDegenerateSine * longest;
  if (t.degenerate) return t;
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
  if (polygon.points.size() < 3) return std::nullopt;
  switch (options.weight) {
    case WeightKind::MaxMin:
      return solve(polygon, MaxMinWeight{options.angle_tolerance});
    case WeightKind::Liepa:
      return solve(polygon, LiepaWeight{options.angle_tolerance});
    case WeightKind::Area:
      return solve(polygon, AreaWeight{});
  }
  return std::nullopt;
}

}  // namespace holefill
