// Holes for the benchmarks: irregular, non-planar loops with fixed seeds, so every run and
// every library (ours, CGAL's) sees the same polygons.
#pragma once

#include <random>

#include "holefill/triangulate.h"
#include "test_meshes.h"

namespace holefill::bench {

// A wavy, noisy loop of n points around the z axis, with the surrounding surface leaning
// outwards as around a hole in a curved mesh.
inline HolePolygon wavy_hole(int n, unsigned seed = 42) {
  std::mt19937 rng(seed);
  HolePolygon polygon;
  polygon.points = testing::random_loop(n, rng, 0.3, 0.35);
  for (int i = 0; i < n; ++i) {
    const Point mid = (polygon.points[i] + polygon.points[(i + 1) % n]) * 0.5;
    polygon.outside_normals.push_back(
        (Point(0, 0, 1) + 0.4 * Point(mid[0], mid[1], 0)).normalized());
  }
  return polygon;
}

}  // namespace holefill::bench
