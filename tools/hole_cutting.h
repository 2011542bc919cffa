// How holefill-make-assets cuts a hole: the faces inside a wavy ball are removed, then the rim is
// cleaned until it is a simple loop.
#pragma once

#include <cmath>
#include <utility>
#include <vector>

#include "asset_mesh.h"

namespace make_assets {

// One term a*sin(k*theta + phase) of a wavy radius.
struct Wave {
  double amplitude;
  int frequency;
  double phase;
};

// A ball around `center` whose radius depends on the angle theta measured around `axis`:
// r(theta) = radius + sum of the waves. A point is inside when its distance to the centre
// is below r(theta) for its own theta.
struct WavyBall {
  Vec3 center;
  Vec3 axis;  // roughly the surface normal at the centre
  double radius;
  std::vector<Wave> waves;

  bool contains(Vec3 p) const {
    const Vec3 n = normalized(axis);
    // Any vector not parallel to n gives a tangent frame (t1, t2).
    const Vec3 helper = std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 t1 = normalized(cross(n, helper));
    const Vec3 t2 = cross(n, t1);
    const Vec3 d = p - center;
    const double theta = std::atan2(dot(d, t2), dot(d, t1));
    double r = radius;
    for (const Wave& w : waves) r += w.amplitude * std::sin(w.frequency * theta + w.phase);
    return norm(d) < r;
  }
};

// Removes the faces inside `region` (only the connected piece that contains the face
// nearest to region.center), then repeats until nothing changes:
//  - remove faces with two or three edges on the new hole's boundary (ears and dangling
//    faces, which would make the loop touch itself);
//  - remove all faces around a vertex that has several boundary loops through it;
//  - keep only the largest connected component.
// Boundary edges that existed before the cut (e.g. the rim of an open patch) are left alone.
Mesh cutHole(const Mesh& mesh, const WavyBall& region);

// The vertex of m nearest to p, and the average normal of the faces around it.
std::pair<Vec3, Vec3> surfacePoint(const Mesh& m, Vec3 p);

}  // namespace make_assets
