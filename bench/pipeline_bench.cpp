// Each stage on the bundled assets (the paper's Table I rows: sphere, heart, bunny).
#include <benchmark/benchmark.h>

#include "holefill/fill.h"
#include "holefill/io.h"

namespace holefill::bench {
namespace {

const char* const kAssets[] = {"sphere.obj", "heart.obj", "bunny.obj"};

// Runs the stages up to `last` on every hole of the asset, timing only the stage `last`.
void stage_on_asset(benchmark::State& state, Stage last) {
  const Mesh original = load_mesh(std::string(HOLEFILL_ASSETS_DIR) + "/" + kAssets[state.range(0)]);
  const auto holes = find_holes(original);
  FillOptions options;
  for (auto _ : state) {
    state.PauseTiming();
    Mesh mesh = original;
    std::vector<HoleFill> fills(holes.size());
    for (std::size_t h = 0; h < holes.size(); ++h) {
      while (static_cast<int>(fills[h].stage()) + 1 < static_cast<int>(last) &&
             advance(mesh, holes[h], fills[h], options)) {
      }
    }
    state.ResumeTiming();
    for (std::size_t h = 0; h < holes.size(); ++h) advance(mesh, holes[h], fills[h], options);
  }
  state.SetLabel(kAssets[state.range(0)]);
}

void BM_StageTriangulate(benchmark::State& s) { stage_on_asset(s, Stage::Triangulated); }
void BM_StageRefine(benchmark::State& s) { stage_on_asset(s, Stage::Refined); }
void BM_StageSmooth(benchmark::State& s) { stage_on_asset(s, Stage::Smoothed); }

void BM_FillAllHoles(benchmark::State& state) {
  const Mesh original = load_mesh(std::string(HOLEFILL_ASSETS_DIR) + "/" + kAssets[state.range(0)]);
  const auto holes = find_holes(original);
  for (auto _ : state) {
    Mesh mesh = original;
    auto fills = fill_holes(mesh, holes, FillOptions{});
    benchmark::DoNotOptimize(fills);
  }
  state.SetLabel(kAssets[state.range(0)]);
}

BENCHMARK(BM_StageTriangulate)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StageRefine)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StageSmooth)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FillAllHoles)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace holefill::bench
