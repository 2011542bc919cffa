// Meshes with islands and gaps for the tests of islands.h and bridge.h: closed shapes with a
// region cut away around pieces left floating in it, or cut in two.
#pragma once

#include <functional>
#include <vector>

#include "holefill/mesh.h"

namespace holefill::testing {

// A closed blob: the icosphere of `levels` with each vertex at radius(direction) from the origin.
using RadiusFunction = std::function<double(const Point& direction)>;
Mesh make_blob(int levels, const RadiusFunction& radius);

// A cap of a closed shape around the origin: the directions within `angle` (radians) of `axis`.
struct Cap {
  Point axis;
  double angle;
  bool contains(const Point& p) const;
};

// `closed` without the faces whose centroid lies in `cut` but in none of `islands` (which stay
// as separate pieces inside the hole), with the vertices left unused removed.
Mesh cut_around_islands(const Mesh& closed, const Cap& cut, const std::vector<Cap>& islands);

// A tube of unit radius around the z axis, `around` vertices round and `along` rows of quads
// 0.1 high, without rows [cut_begin, cut_end) (a tube cut in two), with no isolated vertices.
Mesh tube_cut_in_two(int around, int along, int cut_begin, int cut_end);

// A copy without isolated vertices; the others keep their order.
Mesh without_isolated_vertices(const Mesh& mesh);

// V - E + F over the vertices that some face uses.
long euler_characteristic(const Mesh& mesh);

}  // namespace holefill::testing
