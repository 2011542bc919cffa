// --state-file: what the window shows, written whenever it changes, so that a GUI test waits on
// the state it needs (the keys it sent received, the work done and the window idle, a question
// up, a title) instead of a fixed pause (issue 32). No GL.
#pragma once

#include <filesystem>
#include <string>

namespace holefill::viewer {

struct ViewerState {
  long frames = 0;  // frames drawn
  long keys = 0;    // key presses received (Window::keys_received)
  long closes = 0;  // close requests received (Window::close_requests)
  // Nothing to draw and nothing running or waiting: the loop sleeps until an event.
  bool idle = false;
  bool busy = false;     // the worker runs
  int waiting = 0;       // requests waiting for the worker
  std::string question;  // "none", "save-changes" or "overwrite"
  bool dialog = false;   // a file dialog shows
  std::string title;     // the window's title
  std::string notice;    // the status bar's message (its first line)
  std::string phase;     // the long phase the worker's job is in (Worker::phase), or empty
};

// One "name value" line per field, in the order above.
std::string format_state(const ViewerState& state);

// Writes `state` to `path` when its text differs from the last one written (the frame count
// alone does not count as a change): through a temporary file renamed over `path`, so a reader
// never sees half of it. An empty path writes nothing.
class StateReport {
 public:
  explicit StateReport(std::filesystem::path path) : path_(std::move(path)) {}
  void update(const ViewerState& state);

 private:
  std::filesystem::path path_;
  std::string last_;
};

}  // namespace holefill::viewer
