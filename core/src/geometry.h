// Small triangle geometry the library's stages share (internal).
#pragma once

#include <algorithm>
#include <cmath>

#include "holefill/mesh.h"

namespace holefill::geometry {

// The angle at `corner` of triangle (corner, a, b), in [0, pi]; atan2 keeps it accurate near 0
// and pi, where acos of a dot product does not.
inline double angle_at(const Point& corner, const Point& a, const Point& b) {
  const Point u = a - corner, v = b - corner;
  return std::atan2(OpenMesh::cross(u, v).norm(), OpenMesh::dot(u, v));
}

// The smallest of triangle (a, b, c)'s three angles.
inline double min_angle(const Point& a, const Point& b, const Point& c) {
  return std::min({angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)});
}

// The normal of triangle (a, b, c) by the right-hand rule, its length twice the area.
inline Point area_normal(const Point& a, const Point& b, const Point& c) {
  return OpenMesh::cross(b - a, c - a);
}

// The unit normal of triangle (a, b, c); zero for a degenerate triangle.
inline Point unit_normal(const Point& a, const Point& b, const Point& c) {
  const Point n = area_normal(a, b, c);
  const double length = n.norm();
  return length > 0.0 ? n / length : Point(0.0, 0.0, 0.0);
}

// What measure_triangle reports of one triangle (exact, in radians).
struct TriangleMeasures {
  double min_angle = 0.0;     // the triangle's smallest interior angle
  double max_dihedral = 0.0;  // largest angle between its normal and its neighbours'
  double area = 0.0;
  bool degenerate = false;
};

// The measures of triangle (a, b, c) that the weights use, except its dihedral angle (and its
// smallest angle, left 0, when with_min_angle is false: only maxmin needs the atan2).
TriangleMeasures measure_triangle(const Point& a, const Point& b, const Point& c,
                                  bool with_min_angle = true);

// Angle between two unit normals, radians; pi when either is zero (unknown orientation).
double angle_between_normals(const Point& n1, const Point& n2);

}  // namespace holefill::geometry
