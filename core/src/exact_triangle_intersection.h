// The second, independent test of whether two triangles intersect, which joins the search's own
// (triangle_intersection.h) when fill.cpp decides whether a patch may stay in the mesh ("do no
// harm", patch_intersections.h's `exact_too`), so that a miss of either does not pass: GMP
// rationals on the coordinates as stored, no tolerance, and a different method: each triangle's
// section by the other's plane, compared along the planes' common line. Two triangles intersect
// when the interior of one meets the other, closed; touching along sides or at corners does not
// count. A floating- point filter with a certified error bound settles the pairs that one's plane
// clearly separates, so that only the close calls pay for rationals.
#pragma once

#include <array>

#include "holefill/mesh.h"

namespace holefill::detail {

// Whether the two triangles intersect; false when either is degenerate (zero area, exactly).
bool exactly_intersect(const std::array<Point, 3>& a, const std::array<Point, 3>& b);

// exactly_intersect behind the floating-point filter: the same answer, the rationals only for the
// pairs the filter cannot settle.
bool exactly_intersect_filtered(const std::array<Point, 3>& a, const std::array<Point, 3>& b);

}  // namespace holefill::detail
