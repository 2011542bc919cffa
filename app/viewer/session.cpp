#include "session.h"

#include <algorithm>
#include <exception>

#include "holefill/borders.h"
#include "holefill/errors.h"
#include "holefill/io.h"

namespace holefill::viewer {
namespace {

std::vector<FillStep> without_hole(std::vector<FillStep> log, int hole_id) {
  std::erase_if(log, [hole_id](const FillStep& step) { return step.hole_id == hole_id; });
  return log;
}

// What an undo, a redo or another log change did, for the status bar.
std::string change_notice(LogChange::Kind kind, int selected) {
  const std::string hole = "hole " + std::to_string(selected);
  switch (kind) {
    case LogChange::Kind::Undo:
      return "Undone.";
    case LogChange::Kind::Redo:
      return "Redone.";
    case LogChange::Kind::Reset:
      return "Took the patch of " + hole + " out.";
    case LogChange::Kind::Options:
      return "Filled " + hole + " again with the new options.";
    case LogChange::Kind::Keep:
      return "Kept the compared result for " + hole + ".";
  }
  return {};
}

}  // namespace

bool Session::open(const std::filesystem::path& path, Progress* progress,
                   std::size_t remove_pieces_up_to) {
  // Whether to go on after a phase that took this share of the work.
  const auto go_on = [progress](double done) {
    if (progress) progress->set_fraction(done);
    return !is_cancelled(progress);
  };
  try {
    LoadReport report;
    Mesh mesh = load_mesh(path, &report, threads_);
    if (!go_on(0.6)) return false;
    // The command-line tool's preparation, with its defaults (holefill/prepare.h).
    PrepareOptions preparation;
    preparation.threads = threads_;
    preparation.remove_pieces_up_to = remove_pieces_up_to;
    PreparedMesh prepared = prepare_mesh(mesh, preparation);
    if (!go_on(0.9)) return false;
    std::string text = "Opened " + path.string();
    for (const auto& warning : report.warnings) text += "\n" + warning;
    for (std::size_t i = 0; i < prepared.messages.size(); ++i) {
      // The core names no control that removes the pieces: the panel's button does.
      const bool pieces = static_cast<int>(i) == prepared.pieces_message;
      text +=
          "\n" + prepared.messages[i] + (pieces ? "; \"Remove small pieces\" removes them" : "");
    }
    adopt(std::move(mesh), path.filename().string(), std::move(prepared));
    notice_ = {text, false};
    return true;
  } catch (const std::exception& error) {
    notice_ = {std::string("Could not open ") + error.what(), true};
    return false;
  }
}

void Session::load(Mesh mesh, std::string name) {
  PrepareOptions as_it_is;
  as_it_is.stitch = false;
  as_it_is.threads = threads_;
  PreparedMesh prepared = prepare_mesh(mesh, as_it_is);
  adopt(std::move(mesh), std::move(name), std::move(prepared));
}

void Session::adopt(Mesh mesh, std::string name, PreparedMesh prepared) {
  name_ = std::move(name);
  pieces_ = prepared.pieces;
  welds_ = prepared.weld;
  loaded_version_ = next_serial();
  holes_ = std::move(prepared.holes);
  loaded_ = std::make_shared<const MeshState>(
      MeshState{std::move(mesh), std::vector<HoleFill>(holes_.size())});
  const Mesh& loaded = loaded_->mesh;
  islands_ = find_islands(loaded, holes_, options_.islands);
  borders_.clear();
  fillable_.assign(holes_.size(), false);
  for (const int id : prepared.ids_to_fill) fillable_[id] = true;
  for (const auto& hole : holes_) {
    // An island's loop bounds a piece of its own, but it is filled with its hole.
    borders_.push_back(prepared.classes[hole.id].kind == LoopKind::Border &&
                       islands_.outer[hole.id] < 0);
  }
  log_.clear();
  undo_.clear();
  redo_.clear();
  selected_ = -1;
  revision_ = saved_revision_ = last_revision_ = 0;
  take(loaded_, {});
}

bool Session::save(const std::filesystem::path& path) {
  try {
    std::string unwelded;
    if (welds_.positions == 0) {
      save_mesh(mesh(), path);
    } else {  // the file gets the welds whose holes stayed open taken back, as the CLI writes it
      Mesh copy = mesh();
      unwelded = undo_unused_welds(copy, welds_);
      save_mesh(copy, path);
    }
    saved_revision_ = revision_;
    std::string lost = unwelded.empty() ? "" : "; " + unwelded;
    for (const auto& kind : attributes_not_written(mesh(), path)) lost += "; not written: " + kind;
    notice_ = {"Saved " + path.string() + lost, false};
    return true;
  } catch (const std::exception& error) {
    notice_ = {std::string("Could not save ") + error.what(), true};
    return false;
  }
}

void Session::set_options(const FillOptions& options) {
  if (run(options_request(options))) return;
  options_ = options;
  selection_changed();  // the bridge's gap limit is an option
}

const HoleFeatures& Session::selected_features() const {
  const Hole* hole = selected_ >= 0 ? &holes_.at(selected_) : nullptr;
  return features_.of(loaded_->mesh, loaded_version_, hole, options_.features);
}

std::optional<Stage> Session::next_stage() const {
  if (selected_ < 0) return std::nullopt;
  const HoleFill& fill = state_->fills[selected_];
  if (fill.failed() || fill.stage() == Stage::Smoothed) return std::nullopt;
  return static_cast<Stage>(static_cast<int>(fill.stage()) + 1);
}

bool Session::step(Stage stage) { return run(step_request(stage)); }
bool Session::fill_selected() { return run(fill_selected_request()); }
bool Session::fill_all(std::size_t max_edges) { return run(fill_all_request(max_edges)); }

bool Session::run(const std::optional<FillRequest>& request) {
  if (!request) return false;
  std::optional<FillResult> result = compute(*request);
  const bool ran = request->one_stage ? result->mesh_changed : result->all_ran;
  apply(std::move(*result));
  return ran;
}

bool Session::run(const std::optional<LogChange>& change) {
  if (!change) return false;
  apply(std::move(*compute(*change)));
  return true;
}

std::optional<FillRequest> Session::step_request(Stage stage) const {
  if (!can_step(stage)) return std::nullopt;
  return FillRequest{{selected_}, true, false, options_, {{selected_, joined_}}};
}

std::optional<FillRequest> Session::fill_selected_request() const {
  if (!next_stage()) return std::nullopt;
  return FillRequest{{selected_}, false, false, options_, {{selected_, joined_}}};
}

namespace {

bool unfinished(const HoleFill& fill) { return !fill.failed() && fill.stage() != Stage::Smoothed; }

// "Filled 406 of 416 holes; 10 refused; 2 intersect the mesh; 1 left open."
Notice summary(const FillRequest& request, const std::vector<HoleFill>& fills) {
  const std::vector<int>& hole_ids = request.hole_ids;
  std::size_t filled = 0, refused = 0, intersecting = 0;
  for (const int id : hole_ids) {
    filled += fills[id].stage() == Stage::Smoothed;
    refused += fills[id].failed();
    intersecting += fills[id].self_intersections > 0;
  }
  std::string text =
      "Filled " + std::to_string(filled) + " of " + std::to_string(hole_ids.size()) + " holes";
  if (refused) text += "; " + std::to_string(refused) + " refused (see the hole list)";
  if (intersecting) text += "; " + std::to_string(intersecting) + " intersect the mesh";
  if (request.borders_left) {
    text += "; " + std::to_string(request.borders_left) +
            " left open as flat pieces' rims (select one and Fill to close it)";
  }
  return {text + ".", refused > 0};
}

}  // namespace

std::optional<FillRequest> Session::fill_all_request(std::size_t max_edges) const {
  FillRequest request{{}, false, true, options_, {}};
  for (const auto& hole : holes_) {
    if (!unfinished(state_->fills[hole.id]) || closed_by(hole.id) >= 0) continue;
    const bool stepped = has_steps(hole.id);
    // What the preparation leaves out (a flat piece's rim, a kept border) is no hole to close,
    // unless the user fills it on its own.
    if (!stepped && !fillable_[hole.id] && islands_.outer[hole.id] < 0) {
      ++request.borders_left;
      continue;
    }
    // An island is filled with its hole, unless that hole was filled without it.
    const int outer = islands_.outer[hole.id];
    if (!stepped && outer >= 0 && !has_steps(outer)) continue;
    std::vector<int> joined = default_joined(hole.id);
    std::size_t edges = hole.size();
    for (const int id : joined) edges += holes_[id].size();
    if (max_edges != 0 && edges > max_edges) continue;
    request.hole_ids.push_back(hole.id);
    if (!joined.empty()) request.joined[hole.id] = std::move(joined);
  }
  if (request.hole_ids.empty()) return std::nullopt;
  return request;
}

std::optional<FillResult> Session::compute(const FillRequest& request, Progress* progress) const {
  FillResult result;
  result.state = *state_;
  result.log = log_;
  // One hole's steps keep the states before them, for option changes and undo (replay.h).
  if (request.hole_ids.size() == 1)
    result.checkpoints = continue_checkpoints(checkpoints_, log_, request.hole_ids[0]);
  // Progress counts boundary edges, a rough measure of each hole's share of the work.
  double total = 0.0, done = 0.0;
  for (const int id : request.hole_ids) total += static_cast<double>(holes_[id].size());
  std::vector<std::vector<const Hole*>> groups;
  for (const int id : request.hole_ids) {
    const auto joined = request.joined.find(id);
    groups.push_back(
        loops_of(holes_, id, joined == request.joined.end() ? std::vector<int>{} : joined->second));
  }
  FillSequence sequence(result.state.mesh, groups);
  for (const int id : request.hole_ids) {
    if (progress && progress->cancelled()) return std::nullopt;
    HoleFill& fill = result.state.fills[id];
    while (unfinished(fill)) {
      const auto joined = request.joined.find(id);
      const FillStep step =
          make_step(id, joined == request.joined.end() ? std::vector<int>{} : joined->second,
                    request.options);
      // Until a step runs, the state is the session's own, which the checkpoints may share.
      const bool ran =
          run_step(result.state, holes_, step, &result.checkpoints, progress,
                   result.log.size() == log_.size() ? state_ : nullptr, &sequence, threads_);
      if (progress && progress->cancelled()) return std::nullopt;
      // A failed stage is logged too, so that replay shows the same failure in the hole list.
      if (ran || fill.failed()) result.log.push_back(step);
      result.mesh_changed = result.mesh_changed || ran;
      if (!ran || request.one_stage) break;
    }
    if (fill.failed() && !request.one_stage) {
      // The stages a refused fill did not reach keep their place in the log, so that an option
      // change ("keep cutting patches") replays the whole fill, not only the refused stage.
      const auto logged = std::count_if(result.log.begin(), result.log.end(),
                                        [id](const FillStep& step) { return step.hole_id == id; });
      for (auto stage = logged; stage < static_cast<int>(request.options.last_stage); ++stage) {
        const auto joined = request.joined.find(id);
        result.log.push_back(
            make_step(id, joined == request.joined.end() ? std::vector<int>{} : joined->second,
                      request.options));
      }
    }
    if (fill.failed()) {
      result.all_ran = false;
      result.notice = {"Hole " + std::to_string(id) + ": " + fill.failure.message, true};
    }
    done += static_cast<double>(holes_[id].size());
    if (progress) progress->set_fraction(done / total);
  }
  if (progress && progress->cancelled()) return std::nullopt;
  if (request.summarise) result.notice = summary(request, result.state.fills);
  return result;
}

void Session::apply(FillResult result) {
  remember();
  log_ = std::move(result.log);
  if (result.mesh_changed) revised();
  if (!result.notice.text.empty()) notice_ = std::move(result.notice);
  take(std::make_shared<const MeshState>(std::move(result.state)), std::move(result.checkpoints));
}

bool Session::reset_selected() { return run(reset_request()); }
bool Session::undo() { return run(undo_request()); }
bool Session::redo() { return run(redo_request()); }

LogChange Session::return_to(LogChange::Kind kind, const Snapshot& to) const {
  return {kind,     to.log, to.selected, to.revision, options_of(to.log, to.selected, options_),
          to.joined};
}

std::optional<LogChange> Session::undo_request() const {
  if (undo_.empty()) return std::nullopt;
  return return_to(LogChange::Kind::Undo, undo_.back());
}

std::optional<LogChange> Session::redo_request() const {
  if (redo_.empty()) return std::nullopt;
  return return_to(LogChange::Kind::Redo, redo_.back());
}

std::optional<LogChange> Session::reset_request() const {
  if (selected_ < 0 || !has_steps(selected_)) return std::nullopt;
  return LogChange{
      LogChange::Kind::Reset, without_hole(log_, selected_), selected_, 0, options_, {}};
}

std::optional<LogChange> Session::options_request(const FillOptions& options) const {
  if (selected_ < 0 || !has_steps(selected_) || options == options_) return std::nullopt;
  LogChange change{LogChange::Kind::Options, log_, selected_, 0, options, {}};
  for (auto& step : change.log) {
    if (step.hole_id == selected_) step = make_step(selected_, step.joined, options);
  }
  return change;
}

std::optional<LogChange> Session::keep_request(bool right) const {
  if (!shown_comparison() || comparison_made_ != comparison_wanted_) return std::nullopt;
  FillOptions options = (right ? comparison_->right : comparison_->left).options;
  const Stage last = options.last_stage;
  options.last_stage = options_.last_stage;
  LogChange change{LogChange::Kind::Keep, without_hole(log_, selected_), selected_, 0, options, {}};
  for (int stage = 1; stage <= static_cast<int>(last); ++stage)
    change.log.push_back(make_step(selected_, joined_, options));
  return change;
}

std::optional<ChangeResult> Session::compute(const LogChange& change, Progress* progress) const {
  auto rebuilt =
      rebuild(loaded_, holes_, change.log, change.selected, checkpoints_, progress, threads_);
  if (!rebuilt) return std::nullopt;
  return ChangeResult{change, std::move(*rebuilt)};
}

void Session::apply(ChangeResult result) {
  LogChange& change = result.change;
  switch (change.kind) {
    case LogChange::Kind::Undo:
      redo_.push_back({std::move(log_), selected_, joined_, revision_});
      undo_.pop_back();
      revision_ = change.revision;
      break;
    case LogChange::Kind::Redo:
      undo_.push_back({std::move(log_), selected_, joined_, revision_});
      redo_.pop_back();
      revision_ = change.revision;
      break;
    case LogChange::Kind::Reset:
    case LogChange::Kind::Keep:
      remember();
      revised();
      break;
    case LogChange::Kind::Options:
      // A run of option changes (a slider moved several times) is undone as one.
      if (!last_change_was_options_) remember();
      revised();
      break;
  }
  last_change_was_options_ = change.kind == LogChange::Kind::Options;
  if (change.kind == LogChange::Kind::Keep) compare_ = false;
  log_ = std::move(change.log);
  selected_ = change.selected;
  options_ = change.options;
  take(std::make_shared<const MeshState>(std::move(result.rebuilt.state)),
       std::move(result.rebuilt.checkpoints));
  // Undo and redo bring back the loops shift-click had selected with an unfilled hole (a filled
  // one's are those its steps closed).
  if (change.joined && selected_ >= 0 && !has_steps(selected_)) {
    joined_ = std::move(*change.joined);
    selection_changed();
  }
  // What the last fill said ("Filled 68 of 106 holes") no longer holds.
  notice_ = {change_notice(change.kind, selected_), false};
}

const std::map<int, std::size_t>& Session::mesh_valences() {
  if (valences_version_ != mesh_version_) {
    valences_ = valence_histogram(mesh());
    valences_version_ = mesh_version_;
  }
  return valences_;
}

void Session::set_compare(bool on) {
  compare_ = on;
  ++comparison_wanted_;
}

void Session::set_compare_triangulation_only(bool on) {
  if (on == compare_triangulation_only_) return;
  compare_triangulation_only_ = on;
  ++comparison_wanted_;
}

void Session::set_compare_mode(CompareMode mode) {
  if (mode == compare_mode_) return;
  compare_mode_ = mode;
  ++comparison_wanted_;
}

std::optional<ComparisonRequest> Session::comparison_request() const {
  if (!compare_ || selected_ < 0 || comparison_made_ == comparison_wanted_) return std::nullopt;
  return ComparisonRequest{
      selected_, joined_, options_, compare_mode_, compare_triangulation_only_, comparison_wanted_};
}

std::optional<ComparisonResult> Session::compute(const ComparisonRequest& request,
                                                 Progress* progress) const {
  // The hole as it is before its own steps: the log without them (kept, usually).
  const auto before = rebuild(loaded_, holes_, without_hole(log_, request.hole_id), request.hole_id,
                              checkpoints_, progress, threads_);
  if (!before || (progress && progress->cancelled())) return std::nullopt;
  std::vector<const Hole*> loops{&holes_[request.hole_id]};
  for (const int id : request.joined) loops.push_back(&holes_[id]);
  return ComparisonResult{make_comparison(before->state.mesh, loops, request.options, request.mode,
                                          request.triangulation_only, threads_),
                          request.generation};
}

void Session::apply(ComparisonResult result) {
  comparison_ = std::move(result.comparison);
  comparison_made_ = result.generation;
  comparison_version_ = next_serial();
}

const Comparison* Session::shown_comparison() const {
  if (!compare_ || selected_ < 0 || !comparison_ || comparison_->hole_id != selected_)
    return nullptr;
  return &*comparison_;
}

const Comparison* Session::comparison() {
  if (const auto request = comparison_request()) apply(*compute(*request));
  return shown_comparison();
}

void Session::remember() {
  undo_.push_back({log_, selected_, joined_, revision_});
  if (undo_.size() > kHistoryLimit) undo_.erase(undo_.begin());
  redo_.clear();
  last_change_was_options_ = false;
}

void Session::take(std::shared_ptr<const MeshState> state, Checkpoints checkpoints) {
  state_ = std::move(state);
  checkpoints_ = std::move(checkpoints);
  changed();
  joined_ = default_joined(selected_);
  selection_changed();
}

bool Session::has_steps(int hole_id) const {
  return std::any_of(log_.begin(), log_.end(),
                     [hole_id](const FillStep& step) { return step.hole_id == hole_id; });
}

void Session::revised() { revision_ = ++last_revision_; }

void Session::changed() {
  // Versions are unique across sessions, so a renderer that drew one session notices when
  // another (a mesh opened on the worker) takes its place.
  mesh_version_ = next_serial();
  ++comparison_wanted_;
}

}  // namespace holefill::viewer
