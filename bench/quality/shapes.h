// Closed meshes made in code for the quality benchmark: shapes whose surface is known, with
// constant, varying and mixed-sign curvature.
#pragma once

#include <functional>

#include "holefill/mesh.h"

namespace holefill::quality {

// A unit sphere: an icosahedron subdivided `levels` times, projected to the sphere.
Mesh make_icosphere(int levels);

// The icosphere with every point p moved to radius(p) * p (p on the unit sphere), then scaled
// per axis: ellipsoids, bumpy blobs.
Mesh make_star_shape(int levels, const std::function<double(const Point&)>& radius,
                     const Point& axis_scale);

// A torus around the z axis: ring radius `major`, tube radius `minor`, sampled on a
// `around` x `tube` grid of quads split into two triangles each.
Mesh make_torus(double major, double minor, int around, int tube);

}  // namespace holefill::quality
