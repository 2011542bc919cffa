// Whether two triangles of a mesh intersect other than along what they share: their interiors
// meet, or a side of one passes through the interior of the other. Touching along sides or at
// corners (a T-junction, a shared vertex) does not count. Used to check a patch against the mesh
// around it (patch_intersections.h).
#pragma once

#include <array>
#include <optional>

#include "holefill/mesh.h"

namespace holefill::detail {

// A non-degenerate triangle as the test needs it.
struct Triangle3 {
  std::array<Point, 3> corner;
  Point normal;  // unit
  double size;   // longest edge
};

// The triangle with these corners times `scale` (a power of two, so exact: callers scale
// coordinates near the largest doubles down before their products overflow); nothing when it is
// degenerate at that scale.
std::optional<Triangle3> triangle_from(const std::array<Point, 3>& corners, double scale = 1.0);

// The segment [s0, s1] passes through the triangle's interior (touching its sides or corners
// does not count).
bool segment_enters_triangle(const Point& s0, const Point& s1, const Triangle3& t);

// Two non-degenerate triangles intersect (corners at the same position count as shared). The
// tests use tolerances relative to the triangles' size, so the answer does not depend on scale.
bool triangles_intersect(const Triangle3& t1, const Triangle3& t2);

}  // namespace holefill::detail
