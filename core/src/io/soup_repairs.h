// The repairs build_mesh makes (soup_to_mesh.h) to a soup's triangles before they become a Mesh:
// exact duplicates dropped, faces flipped to agree with their neighbours, faces that would make an
// edge non-manifold marked to be kept apart, and a vertex where closed surfaces touch split into
// one copy per surface.
#pragma once

#include <cstddef>
#include <vector>

#include "holefill/io.h"
#include "mesh_from_triangles.h"

namespace holefill::io {

// Removes triangles with the same corners in the same cyclic order as an earlier one, and their
// entries in `sources` (the face each triangle came from) and `corners` (each when not empty).
std::size_t drop_duplicate_triangles(std::vector<Triangle>& triangles, std::vector<int>& sources,
                                     std::vector<Triangle>& corners);

// How many positions are exactly those of an earlier one.
std::size_t count_duplicate_positions(const std::vector<Point>& positions);

// Orients the triangles, marks those to keep apart and splits the vertices where closed fans
// touch (counted in `report`); returns the marks. `uses` are the triangles' EdgeUses, and serve
// all three (flips keep the edges); they are handed back when they still describe the triangles
// (no vertex split), else freed before the mesh is assembled. `manifold_edges`: no edge is used
// more than twice or twice the same way (any_non_manifold_edge, which the caller knows): then
// nothing is flipped or detached. Whether each repair has anything to do is decided on `threads`
// threads (repair_checks.h); the result is the same on any number.
std::vector<char> make_consistent(std::vector<Triangle>& triangles, std::vector<Triangle>& corners,
                                  std::vector<Point>& positions, std::vector<int>& origin,
                                  LoadReport& report, EdgeUses& uses, bool manifold_edges,
                                  unsigned threads = 1);

}  // namespace holefill::io
