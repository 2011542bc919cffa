// Refinement's relaxation test on one edge (the paper's Step 2: interior edges are swapped until
// they are locally Delaunay), on the four points of the edge's two triangles.
#pragma once

#include "holefill/mesh.h"

namespace holefill::detail {

// Edge a-b between triangles (a, b, c) and (b, a, d) swaps when the angles at c and d sum to more
// than pi + 1e-9 and the swapped edge c-d's opposite angles (at a and b) sum to less than theirs
// - 1e-9, the angles as atan2 gives them. Most edges are decided by cotangents, with margins that
// leave every close call to the angles (see the .cpp), so the answer is always the angles'.
bool should_swap_quad(const Point& a, const Point& b, const Point& c, const Point& d);

}  // namespace holefill::detail
