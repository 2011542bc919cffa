#include "triangle_intersection.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "geometry.h"
#include "holefill/triangulate.h"

namespace holefill::detail {
namespace {

// Relative tolerances: a point this close to a plane (times the triangles' size) lies in it; a
// point this close to a side (relative to the triangle's area) is on it, not inside.
constexpr double kPlaneTolerance = 1e-10;
constexpr double kInsideTolerance = 1e-9;

// The two coordinates to keep when projecting onto the plane with this normal.
std::pair<int, int> projection_axes(const Point& normal) {
  const double x = std::abs(normal[0]), y = std::abs(normal[1]), z = std::abs(normal[2]);
  if (x >= y && x >= z) return {1, 2};
  if (y >= z) return {2, 0};
  return {0, 1};
}

struct Point2 {
  double x, y;
};

Point2 project(const Point& p, std::pair<int, int> axes) { return {p[axes.first], p[axes.second]}; }

double cross2(const Point2& o, const Point2& a, const Point2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

bool strictly_inside2(const Point2& p, const Point2& a, const Point2& b, const Point2& c) {
  const double area = cross2(a, b, c);
  if (area == 0.0) return false;
  const double sign = area > 0.0 ? 1.0 : -1.0, margin = kInsideTolerance * std::abs(area);
  return sign * cross2(a, b, p) > margin && sign * cross2(b, c, p) > margin &&
         sign * cross2(c, a, p) > margin;
}

// Segments [a, b] and [c, d] cross at a point inside both.
bool cross_properly2(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double margin =
      kInsideTolerance * std::hypot(b.x - a.x, b.y - a.y) * std::hypot(d.x - c.x, d.y - c.y);
  auto opposite = [margin](double u, double v) {
    return (u > margin && v < -margin) || (u < -margin && v > margin);
  };
  return opposite(cross2(c, d, a), cross2(c, d, b)) && opposite(cross2(a, b, c), cross2(a, b, d));
}

// Direction u lies strictly inside the wedge spanned by v1 and v2 (an angle below pi), all in
// the plane with this normal.
bool inside_wedge(const Point& u, const Point& v1, const Point& v2, const Point& normal) {
  auto sine = [&normal](const Point& x, const Point& y) {
    const double length = x.norm() * y.norm();
    return length > 0.0 ? OpenMesh::dot(OpenMesh::cross(x, y), normal) / length : 0.0;
  };
  const double turn = sine(v1, v2) > 0.0 ? 1.0 : -1.0;
  return turn * sine(v1, u) > kInsideTolerance && turn * sine(u, v2) > kInsideTolerance;
}

bool in_plane_of(const Triangle3& t, const Point& p, double size) {
  return std::abs(OpenMesh::dot(t.normal, p - t.corner[0])) <= kPlaneTolerance * size;
}

Point centre(const Triangle3& t) { return (t.corner[0] + t.corner[1] + t.corner[2]) / 3.0; }

// Two triangles sharing the corners shared_in_1[0..1] of t1 (shared_in_2 of t2): they meet
// beyond the shared edge only when folded onto each other in one plane.
bool fold_onto_each_other(const Triangle3& t1, const Triangle3& t2, const int* shared_in_1,
                          const int* shared_in_2, double size) {
  const Point& apex1 = t1.corner[3 - shared_in_1[0] - shared_in_1[1]];
  const Point& apex2 = t2.corner[3 - shared_in_2[0] - shared_in_2[1]];
  if (!in_plane_of(t1, apex2, size)) return false;
  const Point& p = t1.corner[shared_in_1[0]];
  const Point& q = t1.corner[shared_in_1[1]];
  return OpenMesh::dot(OpenMesh::cross(q - p, apex1 - p), OpenMesh::cross(q - p, apex2 - p)) > 0.0;
}

// Two triangles sharing corner i of t1 (corner j of t2).
bool meet_beyond_shared_corner(const Triangle3& t1, const Triangle3& t2, int i, int j,
                               double size) {
  const Point& p = t1.corner[i];
  const Point &a = t1.corner[(i + 1) % 3], &b = t1.corner[(i + 2) % 3];
  const Point &c = t2.corner[(j + 1) % 3], &d = t2.corner[(j + 2) % 3];
  if (in_plane_of(t1, c, size) && in_plane_of(t1, d, size)) {
    // In one plane they overlap exactly when their wedges at p do.
    const Point& n = t1.normal;
    return inside_wedge(a - p, c - p, d - p, n) || inside_wedge(b - p, c - p, d - p, n) ||
           inside_wedge(c - p, a - p, b - p, n) || inside_wedge(d - p, a - p, b - p, n);
  }
  return segment_enters_triangle(a, b, t2) || segment_enters_triangle(c, d, t1) ||
         segment_enters_triangle(p, a, t2) || segment_enters_triangle(p, b, t2) ||
         segment_enters_triangle(p, c, t1) || segment_enters_triangle(p, d, t1);
}

}  // namespace

bool segment_enters_triangle(const Point& s0, const Point& s1, const Triangle3& t) {
  const double d0 = OpenMesh::dot(t.normal, s0 - t.corner[0]);
  const double d1 = OpenMesh::dot(t.normal, s1 - t.corner[0]);
  const double tolerance = kPlaneTolerance * std::max(t.size, (s1 - s0).norm());
  if ((d0 > tolerance && d1 > tolerance) || (d0 < -tolerance && d1 < -tolerance)) return false;
  const auto axes = projection_axes(t.normal);
  const Point2 a = project(t.corner[0], axes), b = project(t.corner[1], axes),
               c = project(t.corner[2], axes);
  if (std::abs(d0) <= tolerance && std::abs(d1) <= tolerance) {
    const Point2 p = project(s0, axes), q = project(s1, axes);
    const Point2 middle{(p.x + q.x) / 2, (p.y + q.y) / 2};
    return strictly_inside2(p, a, b, c) || strictly_inside2(q, a, b, c) ||
           strictly_inside2(middle, a, b, c) || cross_properly2(p, q, a, b) ||
           cross_properly2(p, q, b, c) || cross_properly2(p, q, c, a);
  }
  const double along = std::clamp(d0 / (d0 - d1), 0.0, 1.0);
  return strictly_inside2(project(s0 + along * (s1 - s0), axes), a, b, c);
}

std::optional<Triangle3> triangle_from(const std::array<Point, 3>& corners, double scale) {
  Triangle3 t;
  for (int c = 0; c < 3; ++c) t.corner[c] = corners[c] * scale;
  if (geometry::measure_triangle(t.corner[0], t.corner[1], t.corner[2], false).degenerate) {
    return std::nullopt;
  }
  t.normal = OpenMesh::cross(t.corner[1] - t.corner[0], t.corner[2] - t.corner[0]).normalized();
  t.size = std::max({(t.corner[1] - t.corner[0]).norm(), (t.corner[2] - t.corner[1]).norm(),
                     (t.corner[0] - t.corner[2]).norm()});
  return t;
}

bool triangles_intersect(const Triangle3& t1, const Triangle3& t2) {
  const double size = std::max(t1.size, t2.size);
  int shared_in_1[3], shared_in_2[3], shared = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (t1.corner[i] == t2.corner[j]) {
        shared_in_1[shared] = i;
        shared_in_2[shared++] = j;
        break;
      }
    }
  }
  if (shared >= 3) return true;  // the same triangle twice
  if (shared == 2) return fold_onto_each_other(t1, t2, shared_in_1, shared_in_2, size);
  if (shared == 1) return meet_beyond_shared_corner(t1, t2, shared_in_1[0], shared_in_2[0], size);
  for (int i = 0; i < 3; ++i) {
    if (segment_enters_triangle(t1.corner[i], t1.corner[(i + 1) % 3], t2) ||
        segment_enters_triangle(t2.corner[i], t2.corner[(i + 1) % 3], t1)) {
      return true;
    }
  }
  // In one plane, one may lie inside the other with no side crossing a side.
  if (in_plane_of(t1, t2.corner[0], size) && in_plane_of(t1, t2.corner[1], size) &&
      in_plane_of(t1, t2.corner[2], size)) {
    return segment_enters_triangle(centre(t1), centre(t1), t2) ||
           segment_enters_triangle(centre(t2), centre(t2), t1);
  }
  return false;
}

}  // namespace holefill::detail
