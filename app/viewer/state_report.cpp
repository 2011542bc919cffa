#include "state_report.h"

#include <fstream>
#include <system_error>

namespace holefill::viewer {
namespace {

std::string without_frames(const ViewerState& state) {
  ViewerState copy = state;
  copy.frames = 0;
  return format_state(copy);
}

}  // namespace

std::string format_state(const ViewerState& state) {
  const std::string notice = state.notice.substr(0, state.notice.find('\n'));
  return "frames " + std::to_string(state.frames) + "\nkeys " + std::to_string(state.keys) +
         "\ncloses " + std::to_string(state.closes) + "\nidle " + (state.idle ? "1" : "0") +
         "\nbusy " + (state.busy ? "1" : "0") + "\nwaiting " + std::to_string(state.waiting) +
         "\nquestion " + state.question + "\ndialog " + (state.dialog ? "1" : "0") + "\ntitle " +
         state.title + "\nnotice " + notice + "\nphase " + state.phase + "\n";
}

void StateReport::update(const ViewerState& state) {
  if (path_.empty()) return;
  std::string key = without_frames(state);
  if (key == last_) return;
  last_ = std::move(key);
  auto temporary = path_;
  temporary += ".tmp";
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << format_state(state);
    if (!out) return;
  }
  std::error_code error;
  std::filesystem::rename(temporary, path_, error);
}

}  // namespace holefill::viewer
