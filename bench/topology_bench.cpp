// Loading meshes whose topology is awkward: a vertex that thousands of separate fans share (a
// pinch), where stitching and the hole search once took time quadratic in the fans (issue 17:
// 80,000 fans, 103 s).
#include <benchmark/benchmark.h>

#include <array>
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

// A wavy n x n grid whose every triangle has its own three vertices (an exporter that writes
// each face apart), so that stitching welds every edge: the boundary-point index, the matching
// and the T-junction search over about 6 n^2 boundary points.
holefill::Mesh unwelded_grid(int n) {
  holefill::Mesh mesh;
  auto at = [n](int i, int j) {
    const double u = static_cast<double>(i) / (n - 1), v = static_cast<double>(j) / (n - 1);
    return holefill::Point(u, v, 0.1 * std::sin(3 * u) * std::cos(2 * v));
  };
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) {
      for (const auto& corners : {std::array{at(i, j), at(i + 1, j), at(i + 1, j + 1)},
                                  std::array{at(i, j), at(i + 1, j + 1), at(i, j + 1)}}) {
        mesh.add_face(mesh.add_vertex(corners[0]), mesh.add_vertex(corners[1]),
                      mesh.add_vertex(corners[2]));
      }
    }
  }
  return mesh;
}

void BM_StitchUnweldedGrid(benchmark::State& state) {
  const holefill::Mesh unwelded = unwelded_grid(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    state.PauseTiming();
    holefill::Mesh mesh = unwelded;
    state.ResumeTiming();
    benchmark::DoNotOptimize(holefill::stitch_borders(mesh, {}).edges_stitched);
  }
  state.counters["faces"] = static_cast<double>(unwelded.n_faces());
}

}  // namespace

BENCHMARK(BM_StitchUnweldedGrid)->Arg(100)->Arg(320)->Unit(benchmark::kMillisecond);

BENCHMARK(BM_OpenPinchedFans)
    ->RangeMultiplier(4)
    ->Range(1 << 10, 1 << 16)
    ->Complexity()
    ->Unit(benchmark::kMillisecond);
