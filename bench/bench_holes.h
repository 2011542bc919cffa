// Holes for the benchmarks: irregular, non-planar loops with fixed seeds, so every run and
// every library (ours, CGAL's) sees the same polygons.
#pragma once

#include "holefill/triangulate.h"
#include "test_meshes.h"

namespace holefill::bench {

// A wavy, noisy loop of n points around the z axis, with the surrounding surface leaning
// outwards as around a hole in a curved mesh.
using testing::wavy_hole;

}  // namespace holefill::bench
