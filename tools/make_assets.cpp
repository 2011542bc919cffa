// make_assets: writes the bundled test meshes of holefill (see assets/README.md).
//
//   holefill-make-assets <output-dir> <bunny_closed.obj>
//
// <bunny_closed.obj> is the Stanford bunny of the npm package `bunny`, converted by
// tools/bunny_to_obj.js. Everything else is generated here. The program is deterministic:
// no random numbers, every "noise" is a fixed sum of sines written out below.
//
// Each hole is cut the same way: remove the faces whose centroid lies inside a "wavy
// ball" (a ball whose radius varies with the angle around its axis), keep the
// connected piece of removed faces that contains the face nearest to the centre, then
// clean up until the boundary is a simple loop (see cutHole). The result is checked
// (one component, 2-manifold, consistently oriented, no pinched boundary vertex, the
// expected boundary loop sizes) and the program fails if a check does not hold.
//
// The parts: asset_mesh.h (the mesh type, OBJ files), asset_surfaces.h (sphere, heart, torus,
// terrain), hole_cutting.h (the wavy ball, cutHole) and asset_checks.h.

#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "asset_checks.h"
#include "asset_mesh.h"
#include "asset_surfaces.h"
#include "hole_cutting.h"

namespace {

using namespace make_assets;

// Checks the mesh, prints a summary line, and writes the file. Fails unless the faces point
// away from `inside` and each boundary loop size lies in its [min, max] range (largest
// loop first).
void save(const std::string& dir, const std::string& name, const Mesh& m, Vec3 inside,
          const std::vector<std::pair<int, int>>& loopRanges, const std::string& comment) {
  const Topology t = analyze(m);
  std::printf("%-16s V=%5zu F=%5zu components=%d loops=%zu:", name.c_str(), m.points.size(),
              m.faces.size(), t.components, t.loops.size());
  for (int l : t.loops) std::printf(" %d", l);
  std::printf("\n");
  if (coneVolume(m, inside) <= 0) throw std::runtime_error(name + ": faces point inwards");
  bool ok = t.components == 1 && t.loops.size() == loopRanges.size();
  for (size_t i = 0; ok && i < t.loops.size(); ++i)
    ok = loopRanges[i].first <= t.loops[i] && t.loops[i] <= loopRanges[i].second;
  if (!ok) throw std::runtime_error(name + ": boundary loops not as expected");
  writeObj(dir + "/" + name, m, comment);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s <output-dir> <bunny_closed.obj>\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  try {
    const Mesh closedBunny = readObj(argv[2]);
    const Vec3 origin{0, 0, 0};
    // Sphere: one large hole with a wavy, strongly non-convex rim (a star with long arms).
    {
      const Mesh sphere = geodesicSphere(16);
      const Vec3 c = normalized({0.3, -0.4, 0.87});
      const WavyBall region{
          c, c, 1.0, {{0.75, 8, 0.0}, {0.25, 3, 2.1}, {0.1, 13, 0.5}, {0.04, 29, 2.0}}};
      save(dir, "sphere.obj", cutHole(sphere, region), origin, {{380, 430}},
           "unit sphere (geodesic, frequency 16) with one large wavy hole");
    }
    // Heart: cut the hole on a sphere, then push every vertex out along its ray onto the
    // implicit heart surface.
    {
      const Mesh sphere = geodesicSphere(14);
      const Vec3 c = normalized({0.55, -0.8, 0.25});
      // The phase of the 12-arm wave puts both poles between two arms, so the hole stays
      // clear of the heart's singular points (0, 0, 1) and (0, 0, -1).
      const WavyBall region{c, c, 1.1, {{0.8, 12, 2.5}, {0.25, 3, 1.7}, {0.07, 23, 0.9}}};
      Mesh heart = cutHole(sphere, region);
      for (Vec3& p : heart.points) p = projectOntoHeart(p);
      for (Vec3 singular : {Vec3{0, 0, 1}, Vec3{0, 0, -1}})
        if (distanceToBoundary(heart, singular) < 0.1)
          throw std::runtime_error("heart.obj: the hole reaches a singular point");
      save(dir, "heart.obj", heart, origin, {{470, 520}},
           "implicit heart surface with one large wavy hole");
    }
    // Bunny: the closed npm bunny with three holes (back, left haunch on the +z side, chest).
    // The bunny is y-up and faces -x.
    {
      Mesh bunny = closedBunny;
      const auto [back, backN] = surfacePoint(bunny, {1.2, 6.5, 0.4});
      const auto [side, sideN] = surfacePoint(bunny, {2.5, 1.5, 3.0});
      const auto [chest, chestN] = surfacePoint(bunny, {-4.3, 3.0, 0.3});
      bunny = cutHole(bunny, {back, backN, 2.3, {{0.9, 9, 0.3}, {0.35, 14, 1.7}, {0.15, 4, 2.2}}});
      bunny = cutHole(bunny, {side, sideN, 1.4, {{0.45, 4, 0.8}, {0.2, 7, 2.5}}});
      bunny = cutHole(bunny, {chest, chestN, 1.3, {{0.4, 3, 1.1}, {0.15, 6, 0.2}}});
      save(dir, "bunny.obj", bunny, {0, 3, 0}, {{80, 150}, {15, 60}, {15, 60}},
           "Stanford bunny (npm package bunny 1.0.1, public domain) with three holes");
    }
    // Extras for tests: a bumpy open patch with a star-shaped hole (two loops: the outer
    // rim and the hole; faces point up), and a torus with one hole on the outside of the
    // ring and one on the inside.
    {
      const Mesh patch = terrain(24);
      const auto [c, n] = surfacePoint(patch, {0.1, -0.05, 0.0});
      const WavyBall region{c, n, 0.45, {{0.18, 5, 0.0}, {0.05, 11, 1.0}}};
      save(dir, "ragged_disk.obj", cutHole(patch, region), {0, 0, -10}, {{96, 96}, {50, 70}},
           "bumpy height-field patch over [-1,1]^2 with a star-shaped hole");
    }
    {
      Mesh ring = torus(1.0, 0.4, 48, 20);
      const auto [outer, outerN] = surfacePoint(ring, {1.4, 0.0, 0.0});
      const auto [inner, innerN] = surfacePoint(ring, {-0.6, 0.0, 0.0});
      ring = cutHole(ring, {outer, outerN, 0.6, {{0.2, 5, 0.5}, {0.07, 9, 2.0}}});
      ring = cutHole(ring, {inner, innerN, 0.35, {{0.1, 4, 1.0}}});
      save(dir, "torus.obj", ring, origin, {{25, 70}, {15, 50}},
           "torus (R=1, r=0.4) with two holes");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_assets: %s\n", e.what());
    return 1;
  }
  return 0;
}
