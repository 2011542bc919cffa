// The staged pipeline: triangulate -> refine -> smooth, one hole at a time or all at once.
// A HoleFill is one hole's state; advance() runs its next stage, so a viewer can step through
// the stages and inspect the patch in between, and fill_hole() runs them all.
#pragma once

#include <string>
#include <vector>

#include "holefill/bridge.h"
#include "holefill/failure.h"
#include "holefill/features.h"
#include "holefill/hole_selection.h"
#include "holefill/holes.h"
#include "holefill/islands.h"
#include "holefill/mesh.h"
#include "holefill/patch.h"
#include "holefill/progress.h"
#include "holefill/refine.h"
#include "holefill/smooth.h"
#include "holefill/stats.h"
#include "holefill/triangulate.h"

namespace holefill {

struct FillOptions {
  TriangulateOptions triangulate;
  RefineOptions refine;
  SmoothOptions smooth;
  Stage last_stage = Stage::Smoothed;  // fill_hole stops after this stage
  IslandOptions islands;               // fill_holes fills each hole with its islands (islands.h)
  JoinOptions join;                    // how loops filled together are joined (bridge.h)
  // Sharp features continued through a hole (features.h): a hole alone (no islands, no bridge)
  // whose feature lines all match is filled region by region between the continued creases.
  FeatureOptions features;
  // Re-triangulate a hole whose best triangulation intersects the mesh or itself, forbidding the
  // triangles that do (IntersectionAvoidance). Off: the weight's best is always kept.
  bool avoid_intersections = true;
  // Do no harm: a patch that intersects the mesh or an earlier patch is never kept. The hole whose
  // every triangulation tried does (by the search's check or by an independent exact one) is left
  // open, its fill failed with the reason (HoleFill::refused_intersections). True keeps the best
  // patch anyway, its intersections counted in HoleFill::self_intersections.
  bool allow_intersections = false;
  // Threads that plan holes at once (each hole's dynamic program on one of them, or, with fewer
  // holes than threads, a large hole's program on several; a hole filled alone, by advance,
  // advance_joined, fill_hole or a FillSequence, its program on up to this many). 0: every core
  // this process may run on (its affinity mask). The result is the same whatever the number.
  unsigned threads = 0;
  bool operator==(const FillOptions&) const = default;
};

// What the intersection avoidance did for one hole: the weight's best triangulation had
// first_pairs intersecting pairs; `rounds` more solves of the dynamic program were made, each
// forbidding the triangles found intersecting, first with the chosen weight, then with the
// others; `changed` when an intersection-free triangulation (of weight `weight`) replaced it.
struct IntersectionAvoidance {
  std::size_t first_pairs = 0;
  int rounds = 0;
  bool changed = false;
  WeightKind weight = WeightKind::MaxMin;
};

struct StageTimes {
  double triangulate_seconds = 0.0;
  double refine_seconds = 0.0;
  double smooth_seconds = 0.0;
  double check_seconds = 0.0;  // self-intersection and degeneracy checks after the stages
  double avoid_seconds = 0.0;  // re-triangulating to avoid intersections (first check included)
};

// One hole's progress through the pipeline.
struct HoleFill {
  int hole_id = -1;
  std::size_t boundary_edges = 0;
  Patch patch;      // patch.stage is the last stage run (Original: not started)
  Failure failure;  // set when a stage could not run; the mesh is then unchanged
  // The other loops this patch closes with hole_id's: its islands, or the hole bridged to it.
  std::vector<int> joined_holes;
  PatchStats stats;  // after the last stage run
  StageTimes times;
  RefineResult refinement;
  std::string smoothing_note;   // e.g. why fairing fell back to umbrella smoothing
  std::string refinement_note;  // e.g. why refinement was undone
  std::string attributes_note;  // what the patch could not be given, e.g. UVs across a seam
  std::string islands_note;     // why a loop inside the hole was filled apart (islands.h)
  // The sharp features found entering the hole and how they continue (features.h), and, when
  // lines were found but the fill does not follow them, why (the fill is then the paper's).
  HoleFeatures features;
  std::string features_note;
  // The continued creases of the patch as vertex chains (an entry on the hole's boundary, the new
  // vertices along the path, the other entry or the corner vertex); empty when the fill follows
  // no feature. Their edges stay, and their vertices do not move, after triangulation: the
  // regions between them are refined and smoothed each on its own.
  std::vector<std::vector<VertexHandle>> creases;
  // Pairs (patch triangle, other triangle of the mesh or of the patch) that intersect other than
  // along shared vertices and edges, after the last stage run. Stages that would make a patch
  // that did not intersect the mesh intersect it are undone (and say so in their note).
  std::size_t self_intersections = 0;
  // When the hole was left open because its best patch intersected the mesh (do no harm,
  // FillOptions::allow_intersections): the intersecting pairs that patch had (the search's count,
  // or the exact check's where only that one found them). 0 otherwise.
  std::size_t refused_intersections = 0;
  // Smoothed by fairing whatever the options say: the triangulated patch cut the mesh, umbrella
  // smoothing left it so and fairing cleared it (do no harm). smoothing_note says so.
  bool fair_rescue = false;
  IntersectionAvoidance avoidance;

  Stage stage() const { return patch.stage; }
  bool failed() const { return failure.failed(); }
};

// What advance() did.
enum class StageRun {
  Ran,      // the next stage ran; fill.stage() is now that stage
  AllDone,  // every stage had run already: nothing changed
  Failed,   // the stage could not run (now or before): fill.failure says why, mesh unchanged
};

// Runs the next stage on `fill` (which starts as HoleFill{} for `hole`). Throws InvalidHoleError
// (errors.h), changing nothing, when the first stage is to run and `hole` is not a boundary loop
// of `mesh` as it is (is_boundary_loop: a stale Hole, or one of another mesh); so do
// fill_hole, fill_joined_holes, advance_joined and fill_holes (for the holes they select).
// Once options.triangulate.progress is cancelled, the stage running stops within a few hundred
// milliseconds (its dynamic program, refinement, smoothing, the intersection checks; fairing
// between the steps of its solve): Failed, fill.failure of kind FailureKind::Cancelled. The
// mesh is as before the stage when the cancel came before the stage changed it (during the
// dynamic program, the splits, the smoothing); after that (the checks of a refinement) it keeps
// what the stage did, a valid mesh, for a caller that cancels wants none of it and undoing costs
// seconds on a large one.
StageRun advance(Mesh& mesh, const Hole& hole, HoleFill& fill, const FillOptions& options);

// Runs the stages up to options.last_stage on one hole.
HoleFill fill_hole(Mesh& mesh, const Hole& hole, const FillOptions& options);

// Fills the region that several loops bound (a hole and its islands, two holes to bridge; the
// first loop's id becomes the fill's) with one patch, through the same stages (bridge.h).
HoleFill fill_joined_holes(Mesh& mesh, const std::vector<const Hole*>& loops,
                           const FillOptions& options);

// advance() for that region: the first stage joins the loops by bridges and triangulates the
// joined polygon (a failure says why, e.g. no valid bridge); the others refine and smooth the
// patch. fill.boundary_edges counts every loop's edges, fill.joined_holes names loops 1, 2, ...
// One loop: advance() itself.
StageRun advance_joined(Mesh& mesh, const std::vector<const Hole*>& loops, HoleFill& fill,
                        const FillOptions& options);

// Pairs of a patch triangle and another triangle of the mesh (the patch's own included) that
// intersect other than along the vertices and edges they share. Degenerate triangles are skipped.
std::size_t count_patch_intersections(const Mesh& mesh, const Patch& patch);

// Fills the selected holes of `holes` (as find_holes gave them for this mesh), in order, each
// with its islands (options.islands) and the hole bridged to it (loop_groups.h).
// With `progress`: reports the share of holes triangulated and added, and stops when cancelled:
// before any patch is added when the cancel comes during the triangulations (mesh unchanged,
// nothing returned), else before the next hole (the mesh holds exactly the returned fills).
// Running out of memory while triangulating (on any of its threads) throws std::bad_alloc with
// the mesh unchanged.
std::vector<HoleFill> fill_holes(Mesh& mesh, const std::vector<Hole>& holes,
                                 const FillOptions& options, const HoleSelection& selection = {},
                                 Progress* progress = nullptr);

// As above, with the holes' islands already found: `islands` must be
// find_islands(mesh, holes, options.islands) for this mesh as it is (PreparedMesh::islands, when
// the mesh was prepared with these options and not changed since), which spares finding them
// again (serial work: a tenth of what stays on one thread when 20,000 holes are filled on two).
std::vector<HoleFill> fill_holes(Mesh& mesh, const std::vector<Hole>& holes,
                                 const IslandMap& islands, const FillOptions& options,
                                 const HoleSelection& selection = {}, Progress* progress = nullptr);

}  // namespace holefill
