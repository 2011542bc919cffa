// The dynamic program alone, per weight and hole size (the paper's bottleneck, Table I): the full
// search (pruned, and the plain loop for reference) and the restricted search for large holes.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <initializer_list>
#include <thread>

#include "bench_holes.h"

namespace holefill::bench {
namespace {

// Full: threads as the search chooses them (one on a busy machine); OneThread, AllCores: forced.
// WithProgress: one thread, checking a Progress for a cancel (what that costs).
enum class Search { Full, FullOneThread, FullAllCores, WithProgress, PlainLoop, Restricted };

void triangulate(benchmark::State& state, WeightKind weight, Search search) {
  const HolePolygon polygon = wavy_hole(static_cast<int>(state.range(0)));
  TriangulateOptions options{weight};
  options.prune = search != Search::PlainLoop;
  Progress progress;
  if (search == Search::FullOneThread || search == Search::WithProgress) options.threads = 1;
  if (search == Search::WithProgress) options.progress = &progress;
  if (search == Search::FullAllCores) options.threads = std::thread::hardware_concurrency();
  options.restricted.above_edges = 0;  // the full search, whatever the size
  for (auto _ : state) {
    auto result = search == Search::Restricted ? triangulate_polygon_restricted(polygon, options)
                                               : triangulate_polygon(polygon, options);
    benchmark::DoNotOptimize(result);
  }
  state.counters["edges"] = static_cast<double>(state.range(0));
  // The process's peak resident memory so far: a size's own peak when it runs alone, e.g.
  // --benchmark_filter='TriangulateMaxMin/2000$' (later benchmarks inherit earlier peaks).
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  state.counters["peak_rss_MB"] = static_cast<double>(usage.ru_maxrss) / 1024.0;
}

void BM_TriangulateMaxMin(benchmark::State& s) { triangulate(s, WeightKind::MaxMin, Search::Full); }
void BM_TriangulateLiepa(benchmark::State& s) { triangulate(s, WeightKind::Liepa, Search::Full); }
void BM_TriangulateArea(benchmark::State& s) { triangulate(s, WeightKind::Area, Search::Full); }
void BM_TriangulateMaxMinOneThread(benchmark::State& s) {
  triangulate(s, WeightKind::MaxMin, Search::FullOneThread);
}
void BM_TriangulateLiepaOneThread(benchmark::State& s) {
  triangulate(s, WeightKind::Liepa, Search::FullOneThread);
}
void BM_TriangulateMaxMinAllCores(benchmark::State& s) {
  triangulate(s, WeightKind::MaxMin, Search::FullAllCores);
}
void BM_TriangulateLiepaAllCores(benchmark::State& s) {
  triangulate(s, WeightKind::Liepa, Search::FullAllCores);
}
void BM_TriangulateMaxMinWithProgress(benchmark::State& s) {
  triangulate(s, WeightKind::MaxMin, Search::WithProgress);
}
void BM_TriangulateMaxMinPlainLoop(benchmark::State& s) {
  triangulate(s, WeightKind::MaxMin, Search::PlainLoop);
}
void BM_RestrictedMaxMin(benchmark::State& s) {
  triangulate(s, WeightKind::MaxMin, Search::Restricted);
}
void BM_RestrictedLiepa(benchmark::State& s) {
  triangulate(s, WeightKind::Liepa, Search::Restricted);
}

// Runs the benchmark at each hole size, in milliseconds.
void sizes(benchmark::internal::Benchmark* bench, std::initializer_list<int> edges) {
  for (const int n : edges) bench->Arg(n);
  bench->Unit(benchmark::kMillisecond);
}

const bool kRegistered = [] {
  sizes(benchmark::RegisterBenchmark("BM_TriangulateMaxMin", BM_TriangulateMaxMin),
        {50, 100, 200, 400, 500, 800, 2000});
  sizes(benchmark::RegisterBenchmark("BM_TriangulateLiepa", BM_TriangulateLiepa),
        {50, 100, 200, 400, 500, 800, 2000});
  sizes(benchmark::RegisterBenchmark("BM_TriangulateArea", BM_TriangulateArea),
        {50, 100, 200, 400, 500, 800, 2000});
  sizes(
      benchmark::RegisterBenchmark("BM_TriangulateMaxMinOneThread", BM_TriangulateMaxMinOneThread),
      {50, 100, 200, 400, 500, 800, 2000});
  sizes(benchmark::RegisterBenchmark("BM_TriangulateLiepaOneThread", BM_TriangulateLiepaOneThread),
        {50, 100, 200, 400, 500, 800, 2000});
  // Several threads: wall-clock time is what counts (the CPU column has the main thread's only).
  sizes(benchmark::RegisterBenchmark("BM_TriangulateMaxMinAllCores", BM_TriangulateMaxMinAllCores)
            ->UseRealTime(),
        {50, 100, 200, 400, 500, 800, 2000});
  sizes(benchmark::RegisterBenchmark("BM_TriangulateLiepaAllCores", BM_TriangulateLiepaAllCores)
            ->UseRealTime(),
        {50, 100, 200, 400, 500, 800, 2000});
  sizes(benchmark::RegisterBenchmark("BM_TriangulateMaxMinWithProgress",
                                     BM_TriangulateMaxMinWithProgress),
        {100, 500});
  sizes(
      benchmark::RegisterBenchmark("BM_TriangulateMaxMinPlainLoop", BM_TriangulateMaxMinPlainLoop),
      {100, 400});
  sizes(benchmark::RegisterBenchmark("BM_RestrictedMaxMin", BM_RestrictedMaxMin),
        {400, 800, 2000, 5000});
  sizes(benchmark::RegisterBenchmark("BM_RestrictedLiepa", BM_RestrictedLiepa),
        {400, 800, 2000, 5000});
  return true;
}();

}  // namespace
}  // namespace holefill::bench
