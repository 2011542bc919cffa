// Finding holes: every closed loop of boundary halfedges (the 3D polygon P0 ... Pn-1 of the
// paper, in the loop's halfedge order).
#pragma once

#include <vector>

#include "holefill/mesh.h"

namespace holefill {

struct Hole {
  int id = -1;  // position in find_holes' result: 0 is the hole with the most boundary edges
  std::vector<VertexHandle> vertices;     // P0 ... Pn-1
  std::vector<HalfedgeHandle> halfedges;  // halfedges[i] runs vertices[i] -> vertices[i+1 mod n]
  double perimeter = 0.0;
  Point centroid{0.0, 0.0, 0.0};              // mean of the boundary vertices
  double mean_surrounding_edge_length = 0.0;  // over all edges at the boundary vertices
  // A vertex occurs more than once on this loop or on several loops (two holes touch there).
  bool pinched = false;
  // Vertices this loop itself passes through more than once (a pinched loop); 0 for a simple loop.
  std::size_t repeated_vertices = 0;

  std::size_t size() const { return halfedges.size(); }  // boundary edge count
};

// All boundary loops of the mesh, largest first (ties: lowest halfedge index first).
std::vector<Hole> find_holes(const Mesh& mesh);

// Holes that touch at a vertex, or one hole that runs around several gaps between the fans of
// faces at a vertex, may come out of OpenMesh as one loop passing the vertex several times,
// its passes paired in whatever order the faces were added: a patch over that loop would join
// the gaps, and one with three or more passes cannot even be added. This relinks the boundary at
// such a vertex so that each stretch of the loop from the vertex back to it becomes a loop of its
// own, when every stretch is a gap (its two edges at the vertex lie in different fans). A loop
// that runs around a fan's own rim (a bowtie of two fans, nothing between them) is left as it
// is: splitting it there would close each fan on its own back. Only boundary links change (no
// element is added, removed or moved). `holes` are find_holes(mesh); when this returns more than
// 0 (the loops added), find the holes again (find_separated_holes does both).
std::size_t separate_touching_holes(Mesh& mesh, const std::vector<Hole>& holes);

// find_holes, then separate_touching_holes on its loops, and the mesh's loops after that exactly
// as find_holes would give them (only the loops separation split are walked again).
std::vector<Hole> find_separated_holes(Mesh& mesh);
// find_separated_holes where `holes` are find_holes(mesh), found already (beside other work).
std::vector<Hole> separated_holes(Mesh& mesh, std::vector<Hole> holes);

// find_holes(mesh).size(), without describing the loops.
std::size_t count_holes(const Mesh& mesh);

// Whether `hole` is a boundary loop of `mesh` as it is now: each of its halfedges exists, is on
// the boundary, and runs from its vertex to the next one. False for a hole filled since it was
// found (its halfedges have faces), or one of another mesh.
bool is_boundary_loop(const Mesh& mesh, const Hole& hole);

// The loop through one boundary halfedge, as find_holes would describe it (id left at -1).
Hole hole_through(const Mesh& mesh, HalfedgeHandle boundary_halfedge);

}  // namespace holefill
