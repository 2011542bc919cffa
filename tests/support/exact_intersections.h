// An independent, exact check of patch intersections for the tests: GMP rationals on
// the coordinates as stored, no tolerance, and a different method from the library's
// (triangle_intersection.cpp): each triangle's section by the other's plane, compared along the
// planes' common line. Two triangles intersect when the interior of one meets the other, closed;
// touching along sides or at corners does not count.
#pragma once

#include <array>
#include <vector>

#include "holefill/mesh.h"

namespace holefill::testing {

// Whether the two triangles intersect; false when either is degenerate (zero area, exactly).
bool exactly_intersect(const std::array<Point, 3>& a, const std::array<Point, 3>& b);

// Pairs (patch face, other face of the mesh or later patch face) that exactly intersect: the
// library's count_patch_intersections, by brute force.
std::size_t exact_patch_intersections(const Mesh& mesh, const std::vector<FaceHandle>& patch);

}  // namespace holefill::testing
