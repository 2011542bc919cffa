#include "session.h"

#include <algorithm>
#include <exception>

#include "holefill/errors.h"
#include "holefill/io.h"
#include "holefill/stitch.h"

namespace holefill::viewer {

bool Session::open(const std::filesystem::path& path) {
  try {
    LoadReport report;
    Mesh mesh = load_mesh(path, &report);
    const StitchReport stitched = stitch_borders(mesh);
    load(std::move(mesh), path.filename().string());
    std::string text = "Opened " + path.string();
    for (const auto& warning : report.warnings) text += "\n" + warning;
    if (stitched.edges_stitched > 0) {
      text += "\nStitched " + std::to_string(stitched.edges_stitched) + " boundary edges in " +
              std::to_string(stitched.seams) + " seams (" +
              std::to_string(stitched.vertices_merged) + " vertices merged)";
    }
    notice_ = {text, false};
    return true;
  } catch (const std::exception& error) {
    notice_ = {std::string("Could not open ") + error.what(), true};
    return false;
  }
}

void Session::load(Mesh mesh, std::string name) {
  name_ = std::move(name);
  loaded_ = std::move(mesh);
  holes_ = find_holes(loaded_);
  log_.clear();
  undo_.clear();
  redo_.clear();
  selected_ = -1;
  revision_ = saved_revision_ = last_revision_ = 0;
  replay();
}

bool Session::save(const std::filesystem::path& path) {
  try {
    save_mesh(mesh_, path);
    saved_revision_ = revision_;
    notice_ = {"Saved " + path.string(), false};
    return true;
  } catch (const std::exception& error) {
    notice_ = {std::string("Could not save ") + error.what(), true};
    return false;
  }
}

void Session::select(int hole_id) {
  if (hole_id < -1 || hole_id >= static_cast<int>(holes_.size())) hole_id = -1;
  if (hole_id == selected_) return;
  selected_ = hole_id;
  last_change_was_options_ = false;
  comparison_stale_ = true;
  // A stepped hole shows the options it was filled with.
  for (auto it = log_.rbegin(); it != log_.rend(); ++it) {
    if (it->hole_id == hole_id) {
      options_ = it->options;
      break;
    }
  }
}

void Session::set_options(const FillOptions& options) {
  options_ = options;
  comparison_stale_ = true;
  if (selected_ < 0 || !has_steps(selected_)) return;
  if (!last_change_was_options_) remember();
  last_change_was_options_ = true;
  for (auto& step : log_) {
    if (step.hole_id == selected_) step.options = options_;
  }
  revised();
  replay();
}

std::optional<Stage> Session::next_stage() const {
  if (selected_ < 0) return std::nullopt;
  const HoleFill& fill = fills_[selected_];
  if (fill.failed() || fill.stage() == Stage::Smoothed) return std::nullopt;
  return static_cast<Stage>(static_cast<int>(fill.stage()) + 1);
}

bool Session::step(Stage stage) {
  if (!can_step(stage)) return false;
  remember();
  return run_step(selected_);
}

bool Session::fill_selected() {
  if (!next_stage()) return false;
  remember();
  while (next_stage() && run_step(selected_)) {
  }
  return !fills_[selected_].failed();
}

bool Session::fill_all() {
  const auto open = [this](int id) {
    return !fills_[id].failed() && fills_[id].stage() != Stage::Smoothed;
  };
  bool any = false;
  for (int id = 0; id < static_cast<int>(holes_.size()); ++id) any = any || open(id);
  if (!any) return false;
  remember();
  bool all_filled = true;
  for (int id = 0; id < static_cast<int>(holes_.size()); ++id) {
    while (open(id) && run_step(id)) {
    }
    all_filled = all_filled && !fills_[id].failed();
  }
  if (!all_filled) notice_ = {"Some holes could not be filled; see the hole list.", true};
  return all_filled;
}

bool Session::reset_selected() {
  if (selected_ < 0 || !has_steps(selected_)) return false;
  remember();
  std::erase_if(log_, [this](const FillStep& step) { return step.hole_id == selected_; });
  revised();
  replay();
  return true;
}

bool Session::undo() {
  if (undo_.empty()) return false;
  redo_.push_back({log_, selected_, revision_});
  Snapshot snapshot = std::move(undo_.back());
  undo_.pop_back();
  restore(std::move(snapshot));
  return true;
}

bool Session::redo() {
  if (redo_.empty()) return false;
  undo_.push_back({log_, selected_, revision_});
  Snapshot snapshot = std::move(redo_.back());
  redo_.pop_back();
  restore(std::move(snapshot));
  return true;
}

const std::map<int, std::size_t>& Session::mesh_valences() {
  if (valences_version_ != mesh_version_) {
    valences_ = valence_histogram(mesh_);
    valences_version_ = mesh_version_;
  }
  return valences_;
}

void Session::set_compare(bool on) {
  compare_ = on;
  comparison_stale_ = true;
}

void Session::set_compare_triangulation_only(bool on) {
  if (on == compare_triangulation_only_) return;
  compare_triangulation_only_ = on;
  comparison_stale_ = true;
}

void Session::set_compare_mode(CompareMode mode) {
  if (mode == compare_mode_) return;
  compare_mode_ = mode;
  comparison_stale_ = true;
}

const Comparison* Session::comparison() {
  if (!compare_ || selected_ < 0) return nullptr;
  if (comparison_stale_ || !comparison_) {
    // The hole as it is before its own steps: the log without them, replayed.
    Mesh mesh = loaded_;
    std::vector<HoleFill> fills(holes_.size());
    for (const auto& step : log_) {
      if (step.hole_id != selected_)
        advance(mesh, holes_[step.hole_id], fills[step.hole_id], step.options);
    }
    comparison_ = make_comparison(mesh, holes_[selected_], options_, compare_mode_,
                                  compare_triangulation_only_);
    comparison_stale_ = false;
    ++comparison_version_;
  }
  return &*comparison_;
}

void Session::remember() {
  undo_.push_back({log_, selected_, revision_});
  if (undo_.size() > kHistoryLimit) undo_.erase(undo_.begin());
  redo_.clear();
  last_change_was_options_ = false;
}

void Session::restore(Snapshot snapshot) {
  log_ = std::move(snapshot.log);
  selected_ = snapshot.selected;
  revision_ = snapshot.revision;
  last_change_was_options_ = false;
  for (auto it = log_.rbegin(); it != log_.rend(); ++it) {
    if (it->hole_id == selected_) {
      options_ = it->options;
      break;
    }
  }
  replay();
}

void Session::replay() {
  mesh_ = loaded_;
  fills_.assign(holes_.size(), HoleFill{});
  for (const auto& step : log_)
    advance(mesh_, holes_[step.hole_id], fills_[step.hole_id], step.options);
  changed();
}

bool Session::run_step(int hole_id) {
  const bool ran = advance(mesh_, holes_[hole_id], fills_[hole_id], options_);
  // A failed stage is logged too, so that replay shows the same failure in the hole list;
  // only a stage that ran changed the mesh (a failed one leaves it as it was).
  if (ran || fills_[hole_id].failed()) log_.push_back({hole_id, options_});
  if (ran) revised();
  if (fills_[hole_id].failed()) {
    notice_ = {"Hole " + std::to_string(hole_id) + ": " + fills_[hole_id].failure, true};
  }
  changed();
  return ran;
}

bool Session::has_steps(int hole_id) const {
  return std::any_of(log_.begin(), log_.end(),
                     [hole_id](const FillStep& step) { return step.hole_id == hole_id; });
}

void Session::revised() { revision_ = ++last_revision_; }

void Session::changed() {
  ++mesh_version_;
  comparison_stale_ = true;
}

}  // namespace holefill::viewer
