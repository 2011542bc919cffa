// The tests' brute-force use of the library's exact check (core/src/exact_triangle_intersection.h):
// every face of the mesh against every patch face, no index, so that a face the index would miss
// is still compared.
#pragma once

#include <array>
#include <vector>

#include "holefill/mesh.h"

namespace holefill::testing {

// Whether the two triangles intersect, exactly (detail::exactly_intersect).
bool exactly_intersect(const std::array<Point, 3>& a, const std::array<Point, 3>& b);

// Pairs (patch face, other face of the mesh or later patch face) that exactly intersect: the
// library's count_patch_intersections, by brute force.
std::size_t exact_patch_intersections(const Mesh& mesh, const std::vector<FaceHandle>& patch);

}  // namespace holefill::testing
