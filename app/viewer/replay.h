// The session's state as a log of stage steps, and the mesh a log makes. Undo, redo, reset and an
// option change give the session another log; rebuilding its mesh from the loaded one would
// replay every step, so the states before the selected hole's steps are kept (checkpoints) while
// that hole's steps are the last of the log, which is how a user works on one hole: then a
// change of τ re-runs refinement and smoothing on the state after the triangulation, a change of
// smoothing only the smoothing, and undoing the hole's fill takes the state before it. No GL.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "holefill/fill.h"
#include "holefill/fill_sequence.h"
#include "holefill/progress.h"

namespace holefill::viewer {

// "Advance hole hole_id by one stage with these options", together with the loops `joined` (its
// islands, or the hole it is bridged to: advance_joined). A step never changes once logged: an
// option change logs new steps. `serial` names the step (unique across sessions), so two logs
// with the same serials make the same mesh.
struct FillStep {
  int hole_id = -1;
  std::vector<int> joined;
  FillOptions options;
  std::uint64_t serial = 0;
};

// A new serial for a step (or any other version number): unique across sessions and threads.
std::uint64_t next_serial();

// A step of `hole_id` (with `joined`) with `options` (their Progress dropped) and a new serial.
FillStep make_step(int hole_id, std::vector<int> joined, FillOptions options);

// The options hole_id's last step in `log` used; `fallback` when it has none.
FillOptions options_of(const std::vector<FillStep>& log, int hole_id, const FillOptions& fallback);

// What a log makes of the loaded mesh: the mesh and every hole's fill.
struct MeshState {
  Mesh mesh;
  std::vector<HoleFill> fills;
};

// States kept while the steps of hole_id are the log's last: states[k] is the mesh after the
// log's other steps (their serials: `others`) and the first k of `steps`, for k up to the
// stage before the last (the state after every step is the session's mesh itself).
struct Checkpoints {
  int hole_id = -1;
  std::vector<std::uint64_t> others;
  std::vector<FillStep> steps;
  std::vector<std::shared_ptr<const MeshState>> states;
};

// Whether two option sets make the same result in `stage` (Triangulated: the weight, the search,
// the intersection avoidance and how loops are joined; Refined: refinement; Smoothed: smoothing).
bool same_for_stage(Stage stage, const FillOptions& a, const FillOptions& b);

// Starts checkpoints for the next step of `hole_id` on a session whose log is `log`: the ones
// given when they still describe `log`, new (empty) ones when the hole has no step yet, none
// (hole_id -1) when the hole's steps are not the log's last.
Checkpoints continue_checkpoints(const Checkpoints& saved, const std::vector<FillStep>& log,
                                 int hole_id);

// Runs one step on `state`; `progress` reaches the triangulation's dynamic program (a cancel
// stops it: the step then fails, and the caller drops the state). When `checkpoints` follow
// step.hole_id, the state before the step is kept first and the step recorded: `unchanged`
// where the caller has it (a kept state equal to `state`, shared instead of copied: a mesh of a
// million faces is about 100 MB), else a copy. Returns whether the stage ran.
// With `sequence` (over state.mesh), the step runs through it (fill_sequence.h: the same result,
// without looking at the whole mesh at every step). It runs on `threads` threads
// (FillOptions::threads, whatever the step logged: the result is the same).
bool run_step(MeshState& state, const std::vector<Hole>& holes, const FillStep& step,
              Checkpoints* checkpoints, Progress* progress,
              const std::shared_ptr<const MeshState>& unchanged = nullptr,
              FillSequence* sequence = nullptr, unsigned threads = 0);

// The loops a step of `hole_id` with `joined` fills: the hole first, then the joined ones.
std::vector<const Hole*> loops_of(const std::vector<Hole>& holes, int hole_id,
                                  const std::vector<int>& joined);

struct Rebuilt {
  MeshState state;
  Checkpoints checkpoints;  // for hole_id, when its steps are the log's last
};

// The state `log` makes from `loaded` (the mesh as loaded, no fills; kept as the first
// checkpoint when the log's first step is the hole's): from saved's states where they apply (the
// log's steps of saved.hole_id come last, its other steps are saved.others, and the first steps
// have the same options for their stage), else every step from the loaded mesh, on `threads`
// threads (run_step). Reports the share of the steps run and returns nothing once `progress` is
// cancelled.
std::optional<Rebuilt> rebuild(const std::shared_ptr<const MeshState>& loaded,
                               const std::vector<Hole>& holes, const std::vector<FillStep>& log,
                               int hole_id, const Checkpoints& saved, Progress* progress,
                               unsigned threads = 0);

}  // namespace holefill::viewer
