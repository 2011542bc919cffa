// Each stage on the bundled assets (the paper's Table I rows: sphere, heart, bunny).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "cad_parts.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "test_meshes.h"

namespace holefill::bench {
namespace {

const char* const kAssets[] = {"sphere.obj", "heart.obj", "bunny.obj"};

// The seconds the pipeline itself reports for one stage (StageTimes: the stage alone, without the
// self-intersection and degeneracy checks that follow it), which is what Table I times.
double stage_seconds(const StageTimes& times, Stage stage) {
  switch (stage) {
    case Stage::Triangulated:
      return times.triangulate_seconds;
    case Stage::Refined:
      return times.refine_seconds;
    default:
      return times.smooth_seconds;
  }
}

// Runs the stages before `last` on every hole of the asset, then `last`, timing only that stage.
void stage_on_asset(benchmark::State& state, Stage last) {
  const Mesh original = load_mesh(std::string(HOLEFILL_ASSETS_DIR) + "/" + kAssets[state.range(0)]);
  const auto holes = find_holes(original);
  FillOptions options;
  // The stages before `last` run once; each iteration starts from a copy of their result.
  Mesh prepared = original;
  std::vector<HoleFill> prepared_fills(holes.size());
  for (std::size_t h = 0; h < holes.size(); ++h) {
    while (static_cast<int>(prepared_fills[h].stage()) + 1 < static_cast<int>(last) &&
           advance(prepared, holes[h], prepared_fills[h], options) == StageRun::Ran) {
    }
  }
  std::size_t new_vertices = 0;
  for (auto _ : state) {
    Mesh mesh = prepared;
    std::vector<HoleFill> fills = prepared_fills;
    double seconds = 0.0;
    new_vertices = 0;
    for (std::size_t h = 0; h < holes.size(); ++h) {
      advance(mesh, holes[h], fills[h], options);
      seconds += stage_seconds(fills[h].times, last);
      new_vertices += fills[h].patch.new_vertices.size();
    }
    state.SetIterationTime(seconds);
  }
  state.counters["new_vertices"] = static_cast<double>(new_vertices);
  state.SetLabel(kAssets[state.range(0)]);
}

void BM_StageTriangulate(benchmark::State& s) { stage_on_asset(s, Stage::Triangulated); }
void BM_StageRefine(benchmark::State& s) { stage_on_asset(s, Stage::Refined); }
void BM_StageSmooth(benchmark::State& s) { stage_on_asset(s, Stage::Smoothed); }

// Refinement and smoothing against the patch size: a round hole of radius range(0) / 100 in a
// gently curved 161 x 161 grid, from about 200 to 13,000 new vertices. Linear stages keep the
// time per new vertex (the counter) flat.
void stage_scaling(benchmark::State& state, Stage last) {
  const double radius = static_cast<double>(state.range(0)) / 100.0;
  const Mesh grid = testing::make_grid(
      161, [](double x, double y) { return 0.2 * std::sin(3.0 * x) * std::cos(2.0 * y); });
  const Mesh original = testing::without_faces(
      grid, [&](const Point& c) { return std::hypot(c[0] - 0.5, c[1] - 0.5) < radius; });
  const auto holes = find_holes(original);
  FillOptions options;
  std::size_t new_vertices = 0;
  const Hole* hole = nullptr;
  for (const auto& h : holes) {
    if (!hole || h.size() < hole->size()) hole = &h;  // the cut, not the grid's outer border
  }
  Mesh prepared = original;
  HoleFill prepared_fill;
  while (static_cast<int>(prepared_fill.stage()) + 1 < static_cast<int>(last) &&
         advance(prepared, *hole, prepared_fill, options) == StageRun::Ran) {
  }
  double total_seconds = 0.0;
  for (auto _ : state) {
    Mesh mesh = prepared;
    HoleFill fill = prepared_fill;
    advance(mesh, *hole, fill, options);
    const double seconds = stage_seconds(fill.times, last);
    state.SetIterationTime(seconds);
    total_seconds += seconds;
    new_vertices = fill.patch.new_vertices.size();
  }
  state.counters["new_vertices"] = static_cast<double>(new_vertices);
  state.counters["ns_per_new_vertex"] = total_seconds * 1e9 /
                                        static_cast<double>(state.iterations()) /
                                        static_cast<double>(std::max<std::size_t>(new_vertices, 1));
}

void BM_RefineScaling(benchmark::State& s) { stage_scaling(s, Stage::Refined); }
void BM_SmoothScaling(benchmark::State& s) { stage_scaling(s, Stage::Smoothed); }

// The whole pipeline on every hole, with the intersection avoidance on (range(1) = 1) or off.
void fill_all_holes(benchmark::State& state, const Mesh& original) {
  const auto holes = find_holes(original);
  FillOptions options;
  options.avoid_intersections = state.range(1) != 0;
  std::size_t changed = 0;
  for (auto _ : state) {
    Mesh mesh = original;
    auto fills = fill_holes(mesh, holes, options);
    changed = 0;
    for (const auto& fill : fills) changed += fill.avoidance.changed ? 1 : 0;
    benchmark::DoNotOptimize(fills);
  }
  state.counters["avoided"] = static_cast<double>(changed);
}

void BM_FillAllHoles(benchmark::State& state) {
  fill_all_holes(state,
                 load_mesh(std::string(HOLEFILL_ASSETS_DIR) + "/" + kAssets[state.range(0)]));
  state.SetLabel(kAssets[state.range(0)]);
}

// A bent sheet (wall 0.05) with a hole of radius range(0) / 100 across the outside of the bend,
// which the weight's best triangulation cuts through (tests/robust/cad_intersection_test.cpp).
void BM_FillBentSheet(benchmark::State& state) {
  const double radius = static_cast<double>(state.range(0)) / 100.0;
  const Mesh sheet = testing::surface_of(
      {testing::grid_lines({{0.05, 1}, {0.1, 10}}), testing::grid_lines({{0.05, 1}, {0.1, 10}}),
       testing::grid_lines({{0.1, 10}}), [](int i, int j, int) { return i == 0 || j == 0; }});
  fill_all_holes(state, testing::without_faces_where(sheet, [&](const Point& c, const Point& n) {
                   return (n[0] < -0.5 || n[1] < -0.5) && (c - Point(0, 0, 0.5)).norm() < radius;
                 }));
}

// A round hole cut from a wavy range(0) x range(0) grid, whose border is a staircase of the grid's
// triangles: the weight's best plan crosses the steps, so the avoidance forbids the chords through
// the mesh (chords_through_mesh) and solves again. At range(0) = 100 the hole has about 200
// edges; the 1,200-edge hole of bench/NOTEBOOK.md took minutes before the chords were found
// along a bounding-box hierarchy.
void BM_FillStaircaseHole(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Mesh cut = testing::without_faces(
      testing::make_grid(
          n, [](double x, double y) { return 0.05 * std::sin(6 * x) * std::cos(5 * y); }),
      [](const Point& c) { return std::hypot(c[0] - 0.5, c[1] - 0.5) < 0.3; });
  // The round hole is the smaller loop; the grid's outer border has the same centroid.
  const auto holes = find_holes(cut);
  const auto round = std::min_element(
      holes.begin(), holes.end(), [](const Hole& a, const Hole& b) { return a.size() < b.size(); });
  if (round == holes.end()) return state.SkipWithError("no hole cut");
  const HoleSelection just_the_round_hole{.hole_ids = {round->id}};
  for (auto _ : state) {
    Mesh mesh = cut;
    benchmark::DoNotOptimize(fill_holes(mesh, holes, FillOptions{}, just_the_round_hole));
  }
  state.counters["edges"] = static_cast<double>(round->size());
}

BENCHMARK(BM_StageTriangulate)->DenseRange(0, 2)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StageRefine)->DenseRange(0, 2)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StageSmooth)->DenseRange(0, 2)->UseManualTime()->Unit(benchmark::kMillisecond);
// The hole radii (in hundredths) of the scaling benchmarks, timed by the stage's own clock.
void hole_radii(benchmark::internal::Benchmark* bench) {
  for (const int radius : {5, 10, 20, 40}) bench->Arg(radius);
  bench->UseManualTime()->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_RefineScaling)->Apply(hole_radii);
BENCHMARK(BM_SmoothScaling)->Apply(hole_radii);
BENCHMARK(BM_FillAllHoles)->ArgsProduct({{0, 1, 2}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FillBentSheet)->ArgsProduct({{20, 45}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FillStaircaseHole)->Arg(50)->Arg(100)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace holefill::bench
