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

// The loop through one boundary halfedge, as find_holes would describe it (id left at -1).
Hole hole_through(const Mesh& mesh, HalfedgeHandle boundary_halfedge);

}  // namespace holefill
