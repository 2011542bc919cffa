// Room in a mesh's arrays for the patches fill_holes is about to add. The loader leaves an eighth
// more than the file holds (mesh_room.h); patches that add more, refined to the density around
// many holes, made each array outgrow it while the patches were added: a copy into an array twice
// the size, beside the old one and the index of faces near the holes (the peak of the fill).
// Reserving once before that index is built moves the copy to where less is held.
#pragma once

#include <cstddef>

#include "holefill/holes.h"
#include "holefill/mesh.h"
#include "holefill/triangulate.h"

namespace holefill::detail {

struct PatchRoom {
  std::size_t vertices = 0, edges = 0, faces = 0;
  PatchRoom& operator+=(const PatchRoom& other);
};

// An estimate of what one hole's patch adds: its triangulation's faces and inner edges, and with
// `refined` as many faces as the triangulation's area holds triangles of the hole's surroundings
// (equilateral, with its mean surrounding edge length), with the vertices and edges a disk of
// that many faces has inside.
PatchRoom patch_room(const Mesh& mesh, const Hole& hole, const PolygonTriangulation& triangulation,
                     bool refined);

// Reserves room for `added` beyond the mesh's elements (and an eighth more) when it is more than
// the eighth the loader leaves; otherwise does nothing, so that a fill adding little copies no
// array. Never more than twice the elements (and the eighth); nothing when memory is short.
void reserve_patch_room(Mesh& mesh, const PatchRoom& added);

}  // namespace holefill::detail
