// The closed and open surfaces holefill-make-assets cuts its holes into.
#pragma once

#include "asset_mesh.h"

namespace make_assets {

// Geodesic sphere: each face of an icosahedron split into k*k triangles, projected onto
// the unit sphere. 10*k*k + 2 vertices, 20*k*k faces.
Mesh geodesicSphere(int k);

// The point where the ray from the origin in direction d leaves the implicit heart surface
// (asset_surfaces.cpp), which is star-shaped around the origin.
Vec3 projectOntoHeart(Vec3 d);

// A torus around the z axis: major radius R, tube radius r, n x m quads split in two.
Mesh torus(double R, double r, int n, int m);

// A square height field patch over [-1,1]^2 with n x n cells, diagonals alternating.
Mesh terrain(int n);

}  // namespace make_assets
