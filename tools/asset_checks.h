// The checks holefill-make-assets makes on every mesh before it writes it.
#pragma once

#include <vector>

#include "asset_mesh.h"

namespace make_assets {

struct Topology {
  int components = 0;
  std::vector<int> loops;  // edge count of each boundary loop, largest first
};

// Throws unless the mesh is a single consistently oriented 2-manifold component whose
// boundary vertices each lie on exactly one boundary loop.
Topology analyze(const Mesh& m);

// Sum of the signed volumes of the tetrahedra (o, a, b, c) over the faces (a, b, c). For a
// closed surface this is its enclosed volume whatever o is; with holes it is still positive
// when the faces point away from a point o on the inner side.
double coneVolume(const Mesh& m, Vec3 o);

// Distance from p to the nearest boundary vertex of m.
double distanceToBoundary(const Mesh& m, Vec3 p);

}  // namespace make_assets
