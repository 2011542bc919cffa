// The dynamic program alone, per weight and hole size (the paper's bottleneck, Table I).
#include <benchmark/benchmark.h>

#include "bench_holes.h"

namespace holefill::bench {
namespace {

void triangulate(benchmark::State& state, WeightKind weight, bool prune) {
  const HolePolygon polygon = wavy_hole(static_cast<int>(state.range(0)));
  TriangulateOptions options{weight};
  options.prune = prune;
  for (auto _ : state) {
    auto result = triangulate_polygon(polygon, options);
    benchmark::DoNotOptimize(result);
  }
  state.counters["edges"] = static_cast<double>(state.range(0));
}

void BM_TriangulateMaxMin(benchmark::State& s) { triangulate(s, WeightKind::MaxMin, true); }
void BM_TriangulateLiepa(benchmark::State& s) { triangulate(s, WeightKind::Liepa, true); }
void BM_TriangulateArea(benchmark::State& s) { triangulate(s, WeightKind::Area, true); }
void restricted(benchmark::State& state, WeightKind weight) {
  const HolePolygon polygon = wavy_hole(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    auto result = triangulate_polygon_restricted(polygon, {weight});
    benchmark::DoNotOptimize(result);
  }
  state.counters["edges"] = static_cast<double>(state.range(0));
}
void BM_RestrictedMaxMin(benchmark::State& s) { restricted(s, WeightKind::MaxMin); }
void BM_RestrictedLiepa(benchmark::State& s) { restricted(s, WeightKind::Liepa); }
BENCHMARK(BM_RestrictedMaxMin)
    ->Arg(400)
    ->Arg(800)
    ->Arg(2000)
    ->Arg(5000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RestrictedLiepa)
    ->Arg(400)
    ->Arg(800)
    ->Arg(2000)
    ->Arg(5000)
    ->Unit(benchmark::kMillisecond);

void BM_TriangulateMaxMinPlainLoop(benchmark::State& s) {
  triangulate(s, WeightKind::MaxMin, false);
}

BENCHMARK(BM_TriangulateMaxMin)
    ->Arg(50)
    ->Arg(100)
    ->Arg(200)
    ->Arg(400)
    ->Arg(800)
    ->Arg(2000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TriangulateLiepa)
    ->Arg(50)
    ->Arg(100)
    ->Arg(200)
    ->Arg(400)
    ->Arg(800)
    ->Arg(2000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TriangulateArea)
    ->Arg(50)
    ->Arg(100)
    ->Arg(200)
    ->Arg(400)
    ->Arg(800)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TriangulateMaxMinPlainLoop)->Arg(100)->Arg(400)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace holefill::bench
