#include "replay.h"

#include <algorithm>
#include <atomic>
#include <utility>

namespace holefill::viewer {
namespace {

// The states before the triangulation, the refinement and the smoothing.
constexpr std::size_t kKeptStates = 3;

std::vector<std::uint64_t> serials_of_others(const std::vector<FillStep>& log, int hole_id) {
  std::vector<std::uint64_t> serials;
  for (const auto& step : log) {
    if (step.hole_id != hole_id) serials.push_back(step.serial);
  }
  return serials;
}

std::vector<FillStep> steps_of(const std::vector<FillStep>& log, int hole_id) {
  std::vector<FillStep> steps;
  std::copy_if(log.begin(), log.end(), std::back_inserter(steps),
               [hole_id](const FillStep& step) { return step.hole_id == hole_id; });
  return steps;
}

// Whether no step of another hole follows a step of hole_id.
bool steps_come_last(const std::vector<FillStep>& log, int hole_id) {
  const auto first = std::find_if(
      log.begin(), log.end(), [hole_id](const FillStep& step) { return step.hole_id == hole_id; });
  return std::all_of(first, log.end(),
                     [hole_id](const FillStep& step) { return step.hole_id == hole_id; });
}

bool same_serials(const std::vector<FillStep>& a, const std::vector<FillStep>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const FillStep& x, const FillStep& y) { return x.serial == y.serial; });
}

// The stage a hole's k-th step runs (each step runs the next stage, or fails and is the last).
Stage stage_of_step(std::size_t k) { return static_cast<Stage>(static_cast<int>(k) + 1); }

}  // namespace

std::uint64_t next_serial() {
  static std::atomic<std::uint64_t> last{0};
  return ++last;
}

FillStep make_step(int hole_id, std::vector<int> joined, FillOptions options) {
  options.triangulate.progress = nullptr;
  return {hole_id, std::move(joined), std::move(options), next_serial()};
}

FillOptions options_of(const std::vector<FillStep>& log, int hole_id, const FillOptions& fallback) {
  for (auto it = log.rbegin(); it != log.rend(); ++it) {
    if (it->hole_id == hole_id) return it->options;
  }
  return fallback;
}

bool same_for_stage(Stage stage, const FillOptions& a, const FillOptions& b) {
  switch (stage) {
    case Stage::Original:
      return true;
    case Stage::Triangulated:
      return a.triangulate == b.triangulate && a.avoid_intersections == b.avoid_intersections &&
             a.islands == b.islands && a.join == b.join;
    case Stage::Refined:
      return a.refine == b.refine;
    case Stage::Smoothed:
      return a.smooth == b.smooth;
  }
  return false;
}

Checkpoints continue_checkpoints(const Checkpoints& saved, const std::vector<FillStep>& log,
                                 int hole_id) {
  if (hole_id < 0 || !steps_come_last(log, hole_id)) return {};
  const std::vector<FillStep> steps = steps_of(log, hole_id);
  std::vector<std::uint64_t> others = serials_of_others(log, hole_id);
  if (saved.hole_id == hole_id && saved.others == others && same_serials(saved.steps, steps))
    return saved;
  if (steps.empty()) return {hole_id, std::move(others), {}, {}};
  return {};
}

std::vector<const Hole*> loops_of(const std::vector<Hole>& holes, int hole_id,
                                  const std::vector<int>& joined) {
  std::vector<const Hole*> loops{&holes[hole_id]};
  for (const int id : joined) loops.push_back(&holes[id]);
  return loops;
}

bool run_step(MeshState& state, const std::vector<Hole>& holes, const FillStep& step,
              Checkpoints* checkpoints, Progress* progress,
              const std::shared_ptr<const MeshState>& unchanged, FillSequence* sequence,
              unsigned threads) {
  const bool followed = checkpoints && checkpoints->hole_id == step.hole_id;
  // The state before this step, unless it is kept already (states[k] precedes steps[k]).
  if (followed && checkpoints->states.size() == checkpoints->steps.size() &&
      checkpoints->states.size() < kKeptStates) {
    checkpoints->states.push_back(unchanged ? unchanged : std::make_shared<const MeshState>(state));
  }
  FillOptions options = step.options;
  options.triangulate.progress = progress;
  options.threads = threads;
  const std::vector<const Hole*> loops = loops_of(holes, step.hole_id, step.joined);
  HoleFill& fill = state.fills[step.hole_id];
  const bool ran = (sequence ? sequence->step(loops, fill, options)
                             : advance_joined(state.mesh, loops, fill, options)) == StageRun::Ran;
  if (followed) checkpoints->steps.push_back(step);
  return ran;
}

std::optional<Rebuilt> rebuild(const std::shared_ptr<const MeshState>& loaded,
                               const std::vector<Hole>& holes, const std::vector<FillStep>& log,
                               int hole_id, const Checkpoints& saved, Progress* progress,
                               unsigned threads) {
  Rebuilt result;
  std::vector<FillStep> to_run;
  const bool last = hole_id >= 0 && steps_come_last(log, hole_id);
  std::vector<std::uint64_t> others = serials_of_others(log, hole_id);
  if (last && saved.hole_id == hole_id && !saved.states.empty() && saved.others == others) {
    // The hole's first steps that would do what the saved ones did are not run again.
    const std::vector<FillStep> steps = steps_of(log, hole_id);
    std::size_t reused = 0;
    while (
        reused + 1 < saved.states.size() && reused < steps.size() && reused < saved.steps.size() &&
        same_for_stage(stage_of_step(reused), saved.steps[reused].options, steps[reused].options)) {
      ++reused;
    }
    result.state = *saved.states[reused];
    result.checkpoints = {hole_id,
                          std::move(others),
                          std::vector<FillStep>(steps.begin(), steps.begin() + reused),
                          {saved.states.begin(), saved.states.begin() + reused + 1}};
    to_run.assign(steps.begin() + reused, steps.end());
  } else {
    result.state = *loaded;
    if (last) result.checkpoints = {hole_id, std::move(others), {}, {}};
    to_run = log;
  }
  std::vector<std::vector<const Hole*>> groups;
  for (const FillStep& step : to_run) groups.push_back(loops_of(holes, step.hole_id, step.joined));
  FillSequence sequence(result.state.mesh, groups);
  for (std::size_t i = 0; i < to_run.size(); ++i) {
    if (progress && progress->cancelled()) return std::nullopt;
    // A replay from the loaded mesh keeps that mesh, shared, as the state before its first step.
    const bool from_loaded = i == 0 && result.checkpoints.states.empty();
    run_step(result.state, holes, to_run[i], &result.checkpoints, progress,
             from_loaded ? loaded : nullptr, &sequence, threads);
    if (progress) progress->set_fraction(static_cast<double>(i + 1) / to_run.size());
  }
  if (progress && progress->cancelled()) return std::nullopt;
  return result;
}

}  // namespace holefill::viewer
