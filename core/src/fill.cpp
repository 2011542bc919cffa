#include "holefill/fill.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

namespace holefill {
namespace {

template <class Work>
double timed(Work&& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The smoothing stage: the paper's umbrella operator, or fairing with umbrella as the fallback.
void smooth(Mesh& mesh, HoleFill& fill, const SmoothOptions& options) {
  if (options.method == SmoothMethod::Fair) {
    const FairResult result = fair_patch(mesh, fill.patch, options.fair);
    if (result.solved) {
      fill.patch.stage = Stage::Smoothed;
      return;
    }
    fill.smoothing_note = "fairing fell back to umbrella smoothing: " + result.problem;
  }
  smooth_patch(mesh, fill.patch, options);
}

// advance(), with the triangulation already planned when `plan` is given.
bool advance_with(Mesh& mesh, const Hole& hole, HoleFill& fill, const FillOptions& options,
                  const PlannedTriangulation* plan) {
  fill.hole_id = hole.id;
  fill.boundary_edges = hole.size();
  if (fill.failed()) return false;
  switch (fill.stage()) {
    case Stage::Original: {
      TriangulateHoleResult result;
      fill.times.triangulate_seconds += timed([&] {
        result = plan ? apply_triangulation(mesh, hole, *plan)
                      : triangulate_hole(mesh, hole, options.triangulate);
      });
      if (!result.patch) {
        fill.failure = result.failure;
        return false;
      }
      fill.patch = std::move(*result.patch);
      break;
    }
    case Stage::Triangulated:
      fill.times.refine_seconds =
          timed([&] { fill.refinement = refine_patch(mesh, fill.patch, options.refine); });
      break;
    case Stage::Refined:
      fill.times.smooth_seconds = timed([&] { smooth(mesh, fill, options.smooth); });
      break;
    case Stage::Smoothed:
      return false;
  }
  fill.stats = patch_stats(mesh, fill.patch);
  return true;
}

HoleFill fill_planned(Mesh& mesh, const Hole& hole, const FillOptions& options,
                      const PlannedTriangulation* plan) {
  HoleFill fill;
  while (fill.stage() < options.last_stage && advance_with(mesh, hole, fill, options, plan)) {
  }
  return fill;
}

}  // namespace

bool advance(Mesh& mesh, const Hole& hole, HoleFill& fill, const FillOptions& options) {
  return advance_with(mesh, hole, fill, options, nullptr);
}

HoleFill fill_hole(Mesh& mesh, const Hole& hole, const FillOptions& options) {
  return fill_planned(mesh, hole, options, nullptr);
}

bool HoleSelection::includes(const Hole& hole) const {
  if (max_boundary_edges && hole.size() > max_boundary_edges) return false;
  return hole_ids.empty() || std::find(hole_ids.begin(), hole_ids.end(), hole.id) != hole_ids.end();
}

std::vector<HoleFill> fill_holes(Mesh& mesh, const std::vector<Hole>& holes,
                                 const FillOptions& options, const HoleSelection& selection) {
  std::vector<const Hole*> chosen;
  for (const auto& hole : holes) {
    if (selection.includes(hole)) chosen.push_back(&hole);
  }
  // The dynamic programs only read the mesh and dominate the time: run them on every core,
  // largest holes first (holes come sorted by size), then add the patches one by one.
  std::vector<PlannedTriangulation> plans(chosen.size());
  std::vector<double> plan_seconds(chosen.size(), 0.0);
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < chosen.size(); i = next++) {
      plan_seconds[i] =
          timed([&] { plans[i] = plan_triangulation(mesh, *chosen[i], options.triangulate); });
    }
  };
  const unsigned threads =
      std::min<unsigned>(std::max(1u, std::thread::hardware_concurrency()), chosen.size());
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& thread : pool) thread.join();

  std::vector<HoleFill> fills;
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    fills.push_back(fill_planned(mesh, *chosen[i], options, &plans[i]));
    fills.back().times.triangulate_seconds += plan_seconds[i];
  }
  return fills;
}

}  // namespace holefill
