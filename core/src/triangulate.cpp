#include "holefill/triangulate.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>

#include "dp_step.h"
#include "full_search.h"

namespace holefill {

using detail::is_zero;
using detail::unit_normal;

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

geometry::TriangleMeasures geometry::measure_triangle(const Point& a, const Point& b,
                                                      const Point& c, bool with_min_angle) {
  geometry::TriangleMeasures t;
  const double twice_area = OpenMesh::cross(b - a, c - a).norm();
  t.area = 0.5 * twice_area;
  const detail::SmallestAngle angle = detail::smallest_angle(a, b, c, twice_area);
  t.degenerate = angle.degenerate;
  if (!t.degenerate && with_min_angle) t.min_angle = std::atan2(twice_area, angle.dot);
  return t;
}

double geometry::angle_between_normals(const Point& n1, const Point& n2) {
  if (is_zero(n1) || is_zero(n2)) return std::numbers::pi;
  return std::atan2(OpenMesh::cross(n1, n2).norm(), OpenMesh::dot(n1, n2));
}

WeightValue weight_value(const TriangulationQuality& quality, const TriangulateOptions& options) {
  const double chord = detail::weight_key::chord_of_angle(quality.max_dihedral);
  const std::uint64_t degenerate = static_cast<std::uint64_t>(quality.degenerate)
                                   << detail::weight_key::kDegenerateShift;
  return detail::with_weight(options, [&](const auto& weight) {
    return WeightValue{
        detail::weight_key::combine(
            degenerate, detail::weight_key::combine(weight.angle_key(std::tan(quality.min_angle)),
                                                    weight.dihedral_key(chord))),
        quality.area};
  });
}

TriangulationQuality evaluate_triangulation(const HolePolygon& polygon,
                                            const std::vector<std::array<int, 3>>& triangles) {
  TriangulationQuality q;
  q.min_angle = triangles.empty() ? 0.0 : std::numbers::pi;
  const int n = static_cast<int>(polygon.points.size());
  std::map<std::pair<int, int>, Point> first_normal_on_edge;
  for (const auto& t : triangles) {
    const Point &a = polygon.points[t[0]], &b = polygon.points[t[1]], &c = polygon.points[t[2]];
    const geometry::TriangleMeasures m = geometry::measure_triangle(a, b, c);
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
          q.max_dihedral =
              std::max(q.max_dihedral, geometry::angle_between_normals(normal, outside));
        }
        continue;
      }
      const auto [it, inserted] = first_normal_on_edge.emplace(std::make_pair(u, v), normal);
      if (!inserted) {
        q.max_dihedral =
            std::max(q.max_dihedral, geometry::angle_between_normals(normal, it->second));
      }
    }
  }
  return q;
}

namespace {

// Whether a restricted search's triangulation of this quality is worth a full search's time.
bool folds(const TriangulationQuality& quality, const RestrictedSearch& search) {
  return quality.degenerate > 0 || quality.max_dihedral > search.full_search_above_dihedral;
}

}  // namespace

std::optional<PolygonTriangulation> triangulate_polygon(const HolePolygon& polygon,
                                                        const TriangulateOptions& options) {
  if (polygon.points.size() < 3 || polygon.points.size() >= kMaxPolygonSize) return std::nullopt;
  if (!detail::is_canonical(polygon)) {
    return triangulate_polygon(detail::canonical(polygon), options);
  }
  const std::size_t threshold = options.restricted.above_edges;
  const bool above_threshold = threshold > 0 && polygon.points.size() > threshold;
  const bool full_search_allowed = polygon.points.size() <= kMaxFullSearchEdges &&
                                   (!above_threshold || options.restricted.full_search_fallback);
  if (above_threshold) {
    auto restricted = triangulate_polygon_restricted(polygon, options);
    if (restricted && !(full_search_allowed && folds(restricted->quality, options.restricted))) {
      return restricted;
    }
    if (detail::cancelled(options)) return std::nullopt;
  }
  if (!full_search_allowed) return std::nullopt;
  return detail::full_search(polygon, options);
}

}  // namespace holefill
