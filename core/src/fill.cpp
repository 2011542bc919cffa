#include "holefill/fill.h"

#include <algorithm>
#include <chrono>

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

}  // namespace

bool advance(Mesh& mesh, const Hole& hole, HoleFill& fill, const FillOptions& options) {
  fill.hole_id = hole.id;
  fill.boundary_edges = hole.size();
  if (fill.failed()) return false;
  switch (fill.stage()) {
    case Stage::Original: {
      TriangulateHoleResult result;
      fill.times.triangulate_seconds =
          timed([&] { result = triangulate_hole(mesh, hole, options.triangulate); });
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

HoleFill fill_hole(Mesh& mesh, const Hole& hole, const FillOptions& options) {
  HoleFill fill;
  while (fill.stage() < options.last_stage && advance(mesh, hole, fill, options)) {
  }
  return fill;
}

bool HoleSelection::includes(const Hole& hole) const {
  if (max_boundary_edges && hole.size() > max_boundary_edges) return false;
  return hole_ids.empty() || std::find(hole_ids.begin(), hole_ids.end(), hole.id) != hole_ids.end();
}

std::vector<HoleFill> fill_holes(Mesh& mesh, const std::vector<Hole>& holes,
                                 const FillOptions& options, const HoleSelection& selection) {
  std::vector<HoleFill> fills;
  for (const auto& hole : holes) {
    if (selection.includes(hole)) fills.push_back(fill_hole(mesh, hole, options));
  }
  return fills;
}

}  // namespace holefill
