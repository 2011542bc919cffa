// Loading meshes whose topology is awkward: a vertex that thousands of separate fans share (a
// pinch), where stitching and the hole search once took time quadratic in the fans (issue 17:
// 80,000 fans, 103 s).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <string>

#include "holefill/holes.h"
#include "holefill/io.h"
#include "holefill/stitch.h"

namespace {

// `fans` triangles around the origin, each touching the others only there.
std::string pinched_fans_obj(int fans) {
  std::string text = "v 0 0 0\n";
  for (int i = 0; i < fans; ++i) {
    for (const double turn : {i + 0.0, i + 0.4}) {
      const double angle = 2.0 * std::numbers::pi * turn / fans;
      text +=
          "v " + std::to_string(std::cos(angle)) + " " + std::to_string(std::sin(angle)) + " 0\n";
    }
  }
  for (int i = 0; i < fans; ++i) {
    text += "f 1 " + std::to_string(2 + 2 * i) + " " + std::to_string(3 + 2 * i) + "\n";
  }
  return text;
}

// What opening such a file costs: load, stitch (as the CLI and the viewer do), find the holes.
void BM_OpenPinchedFans(benchmark::State& state) {
  const std::string text = pinched_fans_obj(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    holefill::Mesh mesh = holefill::load_mesh_from_memory(text, "fans.obj");
    benchmark::DoNotOptimize(holefill::stitch_borders(mesh, {}).edges_stitched);
    benchmark::DoNotOptimize(holefill::find_holes(mesh).size());
  }
  state.SetComplexityN(state.range(0));
}

}  // namespace

BENCHMARK(BM_OpenPinchedFans)
    ->RangeMultiplier(4)
    ->Range(1 << 10, 1 << 16)
    ->Complexity()
    ->Unit(benchmark::kMillisecond);
