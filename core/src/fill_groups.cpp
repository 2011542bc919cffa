// fill_holes' work on many holes: plan every group, fill each apart from the mesh (both on every
// thread allowed), then splice the patches into the mesh in order (patch_apart.h).
#include <algorithm>
#include <atomic>

#include "available_cores.h"
#include "group_plan.h"
#include "holefill/attributes.h"
#include "parallel_indices.h"
#include "patch_apart.h"
#include "patch_room.h"
#include "per_hole_fill.h"
#include "stage_undo.h"

namespace holefill::detail {
std::vector<HoleFill> fill_groups(Mesh& mesh, const std::vector<Hole>& holes,
                                  const std::vector<LoopGroup>& chosen, const FillOptions& options,
                                  Progress* progress) {
  const std::size_t count = chosen.size();
  // A group counts for the first half of the progress once planned and filled apart, for the
  // second once spliced (fill_holes' promise: one report per hole in each half).
  const auto report = [&](double share) {
    if (progress) progress->set_fraction(share);
  };
  const auto cancelled = [&] { return progress && progress->cancelled(); };
  const unsigned total_threads = options.threads ? options.threads : available_cores();
  const auto threads = static_cast<unsigned>(
      std::clamp<std::size_t>(total_threads, 1, std::max<std::size_t>(1, count)));
  TriangulateOptions triangulate = options.triangulate;
  triangulate.progress = progress;  // a cancel also stops a long dynamic program between rows
  // A number of threads asked for bounds the dynamic programs' too: the threads left over when
  // there are fewer holes than threads go to each hole's program.
  if (options.threads && !triangulate.threads) triangulate.threads = options.threads / threads;

  // The dynamic programs only read the mesh: largest holes first (holes come sorted by size).
  std::vector<GroupPlan> plans(count);
  std::vector<double> plan_seconds(count, 0.0);
  for_each_index(
      count, threads,
      [&](std::size_t i) {
        plan_seconds[i] = timed(
            [&] { plans[i] = plan_group(mesh, holes, chosen[i], triangulate, options.join); });
      },
      cancelled);
  if (cancelled()) return {};

  // Each group is filled on a copy of its surroundings, its patch checked against the faces
  // near it (the index is only read meanwhile).
  PatchRoom estimate;
  std::vector<Box> regions;
  for (const auto& plan : plans) {
    if (plan.plan.triangulation) {
      estimate += patch_room(mesh, plan.polygon, *plan.plan.triangulation,
                             options.last_stage >= Stage::Refined);
    }
    regions.push_back(neighbourhood_of(mesh, plan.polygon.vertices));
  }
  reserve_patch_room(mesh, estimate);
  MeshFaceIndex index(mesh, regions, total_threads, progress);
  if (cancelled()) return {};  // the index is incomplete
  index.set_threads(std::max(1u, total_threads / threads));
  // What a fill learns of its group beside its patch.
  const auto describe = [&](std::size_t i, HoleFill& fill) {
    fill.times.triangulate_seconds += plan_seconds[i];
    fill.boundary_edges = chosen[i].boundary_edges(holes);
    fill.joined_holes.assign(chosen[i].holes.begin() + 1, chosen[i].holes.end());
    fill.islands_note = chosen[i].note;
  };
  if (count == 1) {
    // A single group is filled in the mesh at once, as a patch that must be filled again there:
    // made apart, it would be the same patch (patch_apart.h) after copying its surroundings and
    // splicing it in, serial work that nothing runs beside (2 % of filling one 1,000-edge hole).
    // A cancel takes the patch out again: the mesh is as before, as when filled apart.
    const StageUndo unfilled(mesh, Patch{});
    HoleFill fill = fill_planned(mesh, plans[0].polygon, group_options(chosen[0], options),
                                 &plans[0].plan, &index);
    if (cancelled()) {
      unfilled.undo(mesh, fill.patch);
      return {};
    }
    report(0.5);
    describe(0, fill);
    report(1.0);
    return {std::move(fill)};
  }
  std::vector<PatchApart> aparts(count);
  std::atomic<std::size_t> done{0};
  for_each_index(
      count, threads,
      [&](std::size_t i) {
        aparts[i] = fill_apart(mesh, plans[i].polygon, group_options(chosen[i], options),
                               plans[i].plan, index, regions[i]);
        report(0.5 * static_cast<double>(++done) / count);
      },
      cancelled);
  if (cancelled()) return {};

  // In order, each patch into the mesh; where an earlier one reached it, filled again in the
  // mesh, checked against the faces near it and the patches added before it.
  SplicedPatches spliced(index);
  std::vector<HoleFill> fills;
  for (std::size_t i = 0; i < count && !cancelled(); ++i) {
    PatchApart& apart = aparts[i];
    if (apart.in_mesh || spliced.reached_by(apart) || !splice_patch(mesh, apart)) {
      apart.fill = fill_planned(mesh, plans[i].polygon, group_options(chosen[i], options),
                                &plans[i].plan, &index);
    } else {
      apart.fill.attributes_note = interpolate_patch_attributes(mesh, apart.fill.patch);
    }
    HoleFill& fill = fills.emplace_back(std::move(apart.fill));
    apart = PatchApart{};
    report(0.5 + 0.5 * static_cast<double>(i + 1) / count);
    describe(i, fill);
    for (const auto f : fill.patch.faces) index.add(f.idx(), box_of(mesh, f));
    spliced.add(fill);
  }
  return fills;
}

}  // namespace holefill::detail
