#include "holefill/fill.h"

#include <algorithm>
#include <functional>
#include <new>

#include "advance_unscaled.h"
#include "avoid_intersections.h"
#include "feature_fill.h"
#include "feature_regions.h"
#include "group_plan.h"
#include "hole_triangulation.h"
#include "holefill/attributes.h"
#include "holefill/errors.h"
#include "holefill/loop_groups.h"
#include "patch_intersections.h"
#include "per_hole_fill.h"
#include "safe_scale.h"
#include "stage_undo.h"

namespace holefill {
namespace {

using detail::timed;

// The pairs count_patch_intersections counts; `around` (when given) holds every face of the mesh
// but the patch's, so that only faces near the patch are looked at.
std::size_t count_intersections(const Mesh& mesh, const Patch& patch,
                                const detail::MeshFaceIndex* around) {
  return detail::patch_intersections(mesh, patch, around).size();
}

// ---- The stages ---------------------------------------------------------------------------------
// Each runs one stage on fill.patch and keeps it only when it made no degenerate triangle and no
// new intersection; advance_with alone moves the patch's stage on.

// The cancel that FillOptions carries (TriangulateOptions::progress) stops every stage and check.
const Progress* progress_of(const FillOptions& options) { return options.triangulate.progress; }
bool cancelled(const FillOptions& options) { return is_cancelled(progress_of(options)); }

// Smooths `patch` (the fill's, or one region of it between creases, fairing then on `surface`
// only): the paper's umbrella operator, or fairing with umbrella as the fallback.
void smooth_region(Mesh& mesh, const Patch& patch, HoleFill& fill, const SmoothOptions& options,
                   const std::function<bool(FaceHandle)>* surface, const Progress* progress) {
  if (options.method == SmoothMethod::Fair) {
    const FairResult result = surface
                                  ? fair_patch_within(mesh, patch, options.fair, *surface, progress)
                                  : fair_patch(mesh, patch, options.fair, progress);
    if (result.solved || is_cancelled(progress)) return;
    fill.smoothing_note = "fairing fell back to umbrella smoothing: " + result.problem;
  }
  SmoothOptions umbrella = options;
  umbrella.method = SmoothMethod::Umbrella;
  smooth_patch(mesh, patch, umbrella, progress);
}

// The smoothing stage, on the whole patch or region by region between its creases.
void smooth(Mesh& mesh, HoleFill& fill, const SmoothOptions& options, double feature_angle,
            const Progress* progress) {
  if (fill.creases.empty())
    return smooth_region(mesh, fill.patch, fill, options, nullptr, progress);
  for (const Patch& region : detail::crease_regions(mesh, fill.patch, fill.creases)) {
    if (is_cancelled(progress)) return;
    const auto surface =
        detail::same_side_faces(mesh, region, fill.creases, feature_angle, options.fair.order);
    smooth_region(mesh, region, fill, options, &surface, progress);
  }
}

// The intersecting pairs that the patch has by the search's check, and, where the patch must be
// clean (do no harm), by the independent exact check too.
std::size_t intersections_of(const Mesh& mesh, const Patch& patch,
                             const detail::MeshFaceIndex* index, const FillOptions& options) {
  enter_phase(progress_of(options), phase::kChecking);
  return detail::patch_intersections(mesh, patch, index, !options.allow_intersections,
                                     progress_of(options))
      .size();
}

// Why a finished stage must be undone: it made a degenerate triangle, or it made a patch that
// did not intersect the mesh intersect it. Empty when the stage may stay.
std::string stage_problem(const Mesh& mesh, const HoleFill& fill,
                          const detail::MeshFaceIndex* index, const FillOptions& options,
                          std::size_t& intersections) {
  if (detail::has_degenerate_face(mesh, fill.patch, index ? index->threads() : 1)) {
    return "it made a degenerate (zero-area) triangle";
  }
  intersections = intersections_of(mesh, fill.patch, index, options);
  if (fill.self_intersections == 0 && intersections > 0) {
    return "it made the patch intersect the mesh";
  }
  return {};
}

// Plans the hole's triangulation (or takes `plan`), steers it clear of the mesh when asked, and
// adds it. False, with fill.failure saying why, when no triangulation could be added.
bool triangulate_stage(Mesh& mesh, const Hole& hole, HoleFill& fill, const FillOptions& options,
                       const PlannedTriangulation* plan, const detail::MeshFaceIndex* index) {
  enter_phase(progress_of(options), phase::kTriangulating);
  PlannedTriangulation planned;
  fill.times.triangulate_seconds += timed([&] {
    planned = plan ? *plan : detail::plan_triangulation(mesh, hole, options.triangulate);
  });
  if (options.avoid_intersections) {
    fill.times.avoid_seconds = timed([&] {
      planned = detail::avoid_intersections(mesh, hole, std::move(planned), options.triangulate,
                                            index, fill.avoidance, fill.self_intersections,
                                            !options.allow_intersections);
    });
  }
  if (cancelled(options)) {
    fill.failure = {FailureKind::Cancelled, kCancelledReason};
    return false;
  }
  detail::TriangulateHoleResult result = detail::apply_triangulation(mesh, hole, planned);
  if (!result.patch) {
    fill.failure = result.failure;
    return false;
  }
  fill.patch = std::move(*result.patch);
  if (!options.avoid_intersections) {
    fill.times.check_seconds += timed(
        [&] { fill.self_intersections = intersections_of(mesh, fill.patch, index, options); });
  }
  return true;
}

// Refines the patch; a refinement with remeshing that must be undone is tried again without the
// remeshing, and one that still fails is undone (the patch stays as triangulated). False when a
// cancel stopped it: undone too, the fill failed with the reason.
bool refine_stage(Mesh& mesh, HoleFill& fill, const FillOptions& options,
                  const detail::MeshFaceIndex* index) {
  enter_phase(progress_of(options), phase::kRefining);
  const detail::StageUndo undo(mesh, fill.patch);
  std::size_t intersections = 0;
  fill.times.refine_seconds = 0.0;
  auto refine_and_check = [&](const RefineOptions& refine) {
    std::string problem;
    fill.times.refine_seconds += timed([&] {
      try {
        fill.refinement = fill.creases.empty()
                              ? refine_patch(mesh, fill.patch, refine, progress_of(options))
                              : detail::refine_between_creases(mesh, fill.patch, fill.creases,
                                                               refine, progress_of(options));
      } catch (const std::bad_alloc&) {
        problem = "not enough memory";
      }
    });
    if (problem.empty()) {
      fill.times.check_seconds +=
          timed([&] { problem = stage_problem(mesh, fill, index, options, intersections); });
    }
    return problem;
  };
  std::string problem = refine_and_check(options.refine);
  if (cancelled(options)) {  // not undone: on a large mesh the undo takes seconds
    fill.failure = {FailureKind::Cancelled, kCancelledReason};
    return false;
  }
  if (!problem.empty() && options.refine.remesh) {
    // The paper's refinement alone may be fine where the remeshing on top of it was not.
    undo.undo(mesh, fill.patch);
    RefineOptions without_remesh = options.refine;
    without_remesh.remesh = false;
    const std::string remesh_problem = problem;
    problem = refine_and_check(without_remesh);
    if (problem.empty()) fill.refinement_note = "remeshing undone: " + remesh_problem;
  }
  if (!problem.empty()) {
    undo.undo(mesh, fill.patch);
    fill.refinement = RefineResult{};
    fill.refinement_note = "refinement undone: " + problem;
    return true;
  }
  fill.self_intersections = intersections;
  if (fill.refinement.stopped_at_vertex_cap) {
    fill.refinement_note = "refinement stopped at its cap of " +
                           std::to_string(fill.refinement.vertex_cap) + " new vertices (" +
                           std::to_string(std::lround(options.refine.max_density)) +
                           " times what the boundary's density asks for)";
  }
  return true;
}

// Smooths the patch; a smoothing that must be undone puts the new vertices back where they were.
// False when a cancel stopped it: undone too, the fill failed with the reason.
bool smooth_stage(Mesh& mesh, HoleFill& fill, const FillOptions& options,
                  const detail::MeshFaceIndex* index) {
  enter_phase(progress_of(options), phase::kSmoothing);
  std::vector<Point> positions;
  for (const auto v : fill.patch.new_vertices) positions.push_back(mesh.point(v));
  std::string problem;
  std::size_t intersections = 0;
  SmoothOptions smoothing = options.smooth;
  if (fill.fair_rescue) smoothing.method = SmoothMethod::Fair;
  fill.times.smooth_seconds = timed(
      [&] { smooth(mesh, fill, smoothing, options.features.angle_degrees, progress_of(options)); });
  fill.times.check_seconds +=
      timed([&] { problem = stage_problem(mesh, fill, index, options, intersections); });
  if (problem.empty() && !cancelled(options)) {
    fill.self_intersections = intersections;
    return true;
  }
  for (std::size_t i = 0; i < positions.size(); ++i) {
    mesh.set_point(fill.patch.new_vertices[i], positions[i]);
  }
  if (cancelled(options)) {
    fill.failure = {FailureKind::Cancelled, kCancelledReason};
    return false;
  }
  fill.smoothing_note +=
      (fill.smoothing_note.empty() ? "" : "; ") + std::string("smoothing undone: ") + problem;
  return true;
}

// Whether the stages after triangulation, tried now on the patch, leave it clear of the mesh; the
// patch is then put back as triangulated. They are deterministic, so they will again.
bool later_stages_clear_it(Mesh& mesh, const HoleFill& fill, const FillOptions& options,
                           const detail::MeshFaceIndex* index) {
  const detail::StageUndo triangulated(mesh, fill.patch);
  HoleFill trial = fill;
  refine_stage(mesh, trial, options, index);
  trial.patch.stage = Stage::Refined;
  if (options.last_stage >= Stage::Smoothed) smooth_stage(mesh, trial, options, index);
  const bool clear = trial.self_intersections == 0;
  triangulated.undo(mesh, trial.patch);
  return clear;
}

// later_stages_clear_it, and where umbrella smoothing leaves the patch cutting the mesh, the same
// with fairing, which bends the patch's interior away from the surface around it (a hole next to
// another part, an island across a rim): then the fill is faired (HoleFill::fair_rescue).
bool later_stages_or_fairing_clear_it(Mesh& mesh, HoleFill& fill, const FillOptions& options,
                                      const detail::MeshFaceIndex* index) {
  if (later_stages_clear_it(mesh, fill, options, index)) return true;
  if (options.last_stage < Stage::Smoothed || options.smooth.method == SmoothMethod::Fair) {
    return false;
  }
  HoleFill faired = fill;
  faired.fair_rescue = true;
  if (!later_stages_clear_it(mesh, faired, options, index)) return false;
  fill.fair_rescue = true;
  fill.smoothing_note = "faired instead of umbrella-smoothed: the umbrella's patch cut the mesh";
  return true;
}

// Do no harm, after each stage: a patch that intersects the mesh or an earlier patch (its pairs
// counted by both tests) stays only when intersections are allowed, or, just triangulated, when
// the stages still to run clear it (refinement and smoothing move its interior). Otherwise it is
// taken out of the mesh and the fill fails with the reason. A patch that is no longer the newest
// part of the mesh (a viewer stepping another hole since) cannot be taken out without moving
// other elements: it stays, its intersections reported.
bool may_stay(Mesh& mesh, HoleFill& fill, const FillOptions& options,
              const detail::MeshFaceIndex* index) {
  const std::size_t pairs = fill.self_intersections;
  if (pairs == 0 || options.allow_intersections) return true;
  if (fill.stage() > Stage::Triangulated && fill.stage() < options.last_stage) return true;
  if (fill.stage() == Stage::Triangulated && options.last_stage > Stage::Triangulated &&
      later_stages_or_fairing_clear_it(mesh, fill, options, index)) {
    return true;
  }
  if (!detail::patch_is_newest(mesh, fill.patch)) return true;
  const detail::StageUndo without_patch(mesh, Patch{});
  without_patch.undo(mesh, fill.patch);
  fill.patch = Patch{};
  fill.creases.clear();
  fill.self_intersections = 0;
  if (cancelled(options)) {  // the trial of the later stages was stopped: no verdict
    fill.failure = {FailureKind::Cancelled, kCancelledReason};
    return false;
  }
  fill.refused_intersections = pairs;
  fill.failure = {FailureKind::IntersectsMesh,
                  "every patch tried intersects the mesh (the best in " + std::to_string(pairs) +
                      (pairs == 1 ? " pair" : " pairs") + " of triangles), so it is left open"};
  return false;
}

// advance(), with the triangulation already planned when `plan` is given, and the faces outside
// the patch indexed when `index` is.
StageRun advance_with(Mesh& mesh, const Hole& hole, HoleFill& fill, const FillOptions& options,
                      const PlannedTriangulation* plan, const detail::MeshFaceIndex* index) {
  fill.hole_id = hole.id;
  fill.boundary_edges = hole.size();
  if (fill.failed()) return StageRun::Failed;
  switch (fill.stage()) {
    case Stage::Original:
      // The patch is born Stage::Triangulated, along the hole's sharp features when they continue.
      if (!detail::feature_triangulate_stage(mesh, hole, fill, options, index) &&
          !triangulate_stage(mesh, hole, fill, options, plan, index)) {
        return StageRun::Failed;
      }
      break;
    case Stage::Triangulated:
      if (!refine_stage(mesh, fill, options, index)) return StageRun::Failed;
      fill.patch.stage = Stage::Refined;
      break;
    case Stage::Refined:
      if (!smooth_stage(mesh, fill, options, index)) return StageRun::Failed;
      fill.patch.stage = Stage::Smoothed;
      break;
    case Stage::Smoothed:
      return StageRun::AllDone;
  }
  if (!may_stay(mesh, fill, options, index)) return StageRun::Failed;
  if (cancelled(options)) {  // the measures below take a while on a large patch
    fill.failure = {FailureKind::Cancelled, kCancelledReason};
    return StageRun::Failed;
  }
  // Colours, normals, UVs, materials ... of the new elements.
  fill.attributes_note = interpolate_patch_attributes(mesh, fill.patch);
  fill.stats = patch_stats(mesh, fill.patch, index ? index->threads() : 1);
  return StageRun::Ran;
}

// Runs work() with the mesh at a safe scale (safe_scale.h); returns its result and whether the
// mesh was scaled (then the stats measured meanwhile need measuring again).
template <class Work>
auto at_safe_scale(Mesh& mesh, Work&& work) {
  bool scaled = false;
  auto result = [&] {
    const detail::SafeScale safe(mesh);
    scaled = safe.scaled();
    return work();
  }();
  return std::pair(std::move(result), scaled);
}

void measure_again(const Mesh& mesh, HoleFill& fill) {
  if (fill.stage() != Stage::Original) fill.stats = patch_stats(mesh, fill.patch);
}

// The precondition of every public entry point that is to triangulate: each loop is a boundary
// loop of the mesh as it is (not a stale Hole, nor one of another mesh).
void require_boundary_loops(const Mesh& mesh, const std::vector<const Hole*>& loops) {
  for (const Hole* loop : loops) {
    if (is_boundary_loop(mesh, *loop)) continue;
    throw InvalidHoleError(
        "hole " + std::to_string(loop->id) +
        " is not a boundary loop of this mesh: it was filled since it was "
        "found, or found on another mesh (find_holes gives the loops as they are)");
  }
}

// Loops joined by bridges are triangulated with constraints of their own (bridge.h), which the
// intersection avoidance's solves would not keep: their plan stays as it is.
// One group filled alone (advance, fill_hole): a number of threads asked for bounds its dynamic
// program too, as fill_groups bounds each group's.
FillOptions with_threads_alone(FillOptions options) {
  if (options.threads && !options.triangulate.threads)
    options.triangulate.threads = options.threads;
  return options;
}

FillOptions without_avoidance(FillOptions options) {
  options.avoid_intersections = false;
  return options;
}

}  // namespace

HoleFill detail::fill_planned(Mesh& mesh, const Hole& hole, const FillOptions& options,
                              const PlannedTriangulation* plan,
                              const detail::MeshFaceIndex* index) {
  HoleFill fill;
  while (fill.stage() < options.last_stage &&
         advance_with(mesh, hole, fill, options, plan, index) == StageRun::Ran) {
  }
  return fill;
}

FillOptions detail::group_options(const LoopGroup& group, const FillOptions& options) {
  return group.holes.size() > 1 ? without_avoidance(options) : options;
}

std::size_t count_patch_intersections(const Mesh& mesh, const Patch& patch) {
  return count_intersections(mesh, patch, nullptr);
}

StageRun advance(Mesh& mesh, const Hole& hole, HoleFill& fill, const FillOptions& options) {
  return advance_joined(mesh, {&hole}, fill, options);
}

HoleFill fill_hole(Mesh& mesh, const Hole& hole, const FillOptions& options) {
  require_boundary_loops(mesh, {&hole});
  auto [fill, scaled] = at_safe_scale(mesh, [&] {
    return detail::fill_planned(mesh, hole, with_threads_alone(options), nullptr, nullptr);
  });
  if (scaled) measure_again(mesh, fill);
  return fill;
}

HoleFill fill_joined_holes(Mesh& mesh, const std::vector<const Hole*>& loops,
                           const FillOptions& options) {
  HoleFill fill;
  while (fill.stage() < options.last_stage &&
         advance_joined(mesh, loops, fill, options) == StageRun::Ran) {
  }
  return fill;
}

StageRun advance_joined(Mesh& mesh, const std::vector<const Hole*>& loops, HoleFill& fill,
                        const FillOptions& options) {
  if (fill.stage() == Stage::Original && !fill.failed()) require_boundary_loops(mesh, loops);
  const auto [advanced, scaled] = at_safe_scale(
      mesh, [&] { return detail::advance_unscaled(mesh, loops, fill, options, nullptr); });
  if (scaled) measure_again(mesh, fill);
  return advanced;
}

StageRun detail::advance_unscaled(Mesh& mesh, const std::vector<const Hole*>& loops, HoleFill& fill,
                                  const FillOptions& given, const MeshFaceIndex* index) {
  const FillOptions options = with_threads_alone(given);
  if (loops.size() == 1) return advance_with(mesh, *loops.front(), fill, options, nullptr, index);
  StageRun advanced;
  if (fill.stage() != Stage::Original || fill.failed()) {
    advanced = advance_with(mesh, *loops.front(), fill, options, nullptr, index);
  } else {
    JoinedLoops joined;
    const double seconds =
        timed([&] { joined = plan_joined_loops(mesh, loops, options.triangulate, options.join); });
    fill.times.triangulate_seconds += seconds;
    advanced =
        advance_with(mesh, joined.polygon, fill, without_avoidance(options), &joined.plan, index);
  }
  fill.boundary_edges = 0;
  fill.joined_holes.clear();
  for (const Hole* loop : loops) {
    fill.boundary_edges += loop->size();
    if (loop != loops.front()) fill.joined_holes.push_back(loop->id);
  }
  return advanced;
}

std::vector<HoleFill> fill_holes(Mesh& mesh, const std::vector<Hole>& holes,
                                 const FillOptions& options, const HoleSelection& selection,
                                 Progress* progress) {
  return fill_holes(mesh, holes, find_islands(mesh, holes, options.islands), options, selection,
                    progress);
}

std::vector<HoleFill> fill_holes(Mesh& mesh, const std::vector<Hole>& holes,
                                 const IslandMap& islands, const FillOptions& options,
                                 const HoleSelection& selection, Progress* progress) {
  std::vector<LoopGroup> chosen;
  for (auto& group : group_loops(mesh, holes, islands, selection.bridges, options.join)) {
    if (detail::selects(selection, group, holes)) chosen.push_back(std::move(group));
  }
  for (const auto& group : chosen) {
    std::vector<const Hole*> loops;
    for (const int id : group.holes) loops.push_back(&holes[id]);
    require_boundary_loops(mesh, loops);
  }
  auto [fills, scaled] = at_safe_scale(
      mesh, [&] { return detail::fill_groups(mesh, holes, chosen, options, progress); });
  if (scaled) {
    for (auto& fill : fills) measure_again(mesh, fill);
  }
  return std::move(fills);
}

}  // namespace holefill
