// Session: which loops the selection takes (a hole, its islands, a hole to bridge to), kept
// apart from the stage machine in session.cpp.
#include <algorithm>
#include <string>

#include "holefill/loop_groups.h"
#include "session.h"

namespace holefill::viewer {
namespace {

bool contains(const std::vector<int>& ids, int id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

}  // namespace

void Session::select(int hole_id) {
  if (hole_id < -1 || hole_id >= static_cast<int>(holes_.size())) hole_id = -1;
  if (hole_id >= 0 && closed_by(hole_id) >= 0) {
    hole_id = closed_by(hole_id);
  } else if (hole_id >= 0 && !has_steps(hole_id)) {
    // An island goes with its hole while neither is filled.
    const int outer = islands_.outer[hole_id];
    if (outer >= 0 && !has_steps(outer)) hole_id = outer;
  }
  if (hole_id == selected_) return;
  selected_ = hole_id;
  last_change_was_options_ = false;
  // A stepped hole shows the options it was filled with.
  options_ = options_of(log_, hole_id, options_);
  joined_ = default_joined(hole_id);
  selection_changed();
}

bool Session::in_selection(int hole_id) const {
  return hole_id >= 0 && (hole_id == selected_ || contains(joined_, hole_id));
}

bool Session::toggle(int hole_id) {
  if (hole_id < 0 || hole_id >= static_cast<int>(holes_.size())) return false;
  if (selected_ < 0) {
    select(hole_id);
    return true;
  }
  if (has_steps(selected_)) {
    notice_ = {"Hole " + std::to_string(selected_) +
                   " is filled: reset it (Delete) to change the loops it closes.",
               true};
    return false;
  }
  if (hole_id == selected_) {
    if (joined_.empty()) {
      select(-1);
      return true;
    }
    selected_ = joined_.front();
    joined_.erase(joined_.begin());
  } else if (contains(joined_, hole_id)) {
    std::erase(joined_, hole_id);
  } else if (has_steps(hole_id) || closed_by(hole_id) >= 0) {
    notice_ = {"Hole " + std::to_string(hole_id) + " is filled already.", true};
    return false;
  } else {
    joined_.push_back(hole_id);
  }
  selection_changed();
  return true;
}

int Session::closed_by(int hole_id) const {
  for (const auto& fill : state_->fills) {
    if (fill.stage() != Stage::Original && contains(fill.joined_holes, hole_id))
      return fill.hole_id;
  }
  return -1;
}

std::vector<int> Session::default_joined(int hole_id) const {
  if (hole_id < 0) return {};
  for (const auto& step : log_) {
    if (step.hole_id == hole_id) return step.joined;
  }
  std::vector<int> joined;
  for (const int island : islands_.islands[hole_id]) {
    if (!has_steps(island) && closed_by(island) < 0) joined.push_back(island);
  }
  return joined;
}

void Session::selection_changed() {
  ++comparison_wanted_;
  bridge_problem_.clear();
  if (selected_ < 0 || joined_.size() != 1) {
    bridge_problem_ = "Select two loops to bridge: click one, shift-click the other.";
    return;
  }
  if (has_steps(selected_)) {
    bridge_problem_ = "Hole " + std::to_string(selected_) + " is filled already.";
    return;
  }
  // The command line's check (--bridge): the loops of the pair alone, at most max_gap apart.
  const std::size_t n = holes_.size();
  const IslandMap none{std::vector<std::vector<int>>(n), std::vector<int>(n, -1),
                       std::vector<std::string>(n)};
  for (const auto& group :
       group_loops(mesh(), holes_, none, {{selected_, joined_.front()}}, options_.join)) {
    if (contains(group.holes, selected_)) bridge_problem_ = group.problem.message;
  }
}

}  // namespace holefill::viewer
