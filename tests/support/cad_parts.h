// CAD-like parts made in code for the intersection tests: solids made of boxes on a
// grid with uneven spacing (so that walls can be thin), as a CAD export would triangulate them,
// and holes cut out of their surface.
#pragma once

#include <functional>
#include <vector>

#include "holefill/mesh.h"

namespace holefill::testing {

// A solid made of grid cells: cell (i, j, k) spans [xs[i], xs[i+1]] x [ys[j], ys[j+1]] x
// [zs[k], zs[k+1]] and is part of the solid when filled(i, j, k). Cells must not touch only
// along an edge or a corner (the surface would not be manifold).
struct CellSolid {
  std::vector<double> xs, ys, zs;
  std::function<bool(int, int, int)> filled;
};

// The solid's closed, outward-oriented surface: each grid square between a filled and an empty
// cell as two triangles.
Mesh surface_of(const CellSolid& solid);

// Grid lines from 0 in the given steps, each repeated `count` times: {{0.1, 1}, {0.2, 4}} gives
// 0, 0.1, 0.3, 0.5, 0.7, 0.9.
std::vector<double> grid_lines(const std::vector<std::pair<double, int>>& steps);

}  // namespace holefill::testing
