// When the window draws (issue 31): at once after an event, and for a few frames more (Dear
// ImGui lays a window out and opens a popup over two or three frames); while work runs, about 30
// times a second so that its progress moves, but never more than half the time when frames are
// slow (a big mesh under a software renderer), so that the work keeps the cores; otherwise not
// at all: the loop sleeps in the
// window system until an event comes, and an idle window costs no CPU. The camera moves only
// with the mouse and keys, so their events keep it drawing while it moves. No GL, no window.
#pragma once

#include <algorithm>
#include <optional>

namespace holefill::viewer {

class FramePacer {
 public:
  static constexpr int kSettleFrames = 3;
  static constexpr double kBusySeconds = 1.0 / 30.0;

  // Something happened (an event came, the worker finished): the next frames draw.
  void wake() { frames_left_ = kSettleFrames; }
  // How long the loop may wait for events before its next frame: 0 while frames are left to
  // settle; while `busy`, kBusySeconds or the last frame's time, whichever is longer; else
  // nothing (until an event comes).
  std::optional<double> wait_before_frame(bool busy) const {
    if (frames_left_ > 0) return 0.0;
    if (busy) return std::max(kBusySeconds, last_frame_seconds_);
    return std::nullopt;
  }
  // A frame was drawn in `seconds`.
  void frame_drawn(double seconds = 0.0) {
    if (frames_left_ > 0) --frames_left_;
    last_frame_seconds_ = seconds;
  }
  // True when the next frame would wait for an event: nothing is left to draw.
  bool idle(bool busy) const { return !wait_before_frame(busy).has_value(); }

 private:
  int frames_left_ = kSettleFrames;
  double last_frame_seconds_ = 0.0;
};

}  // namespace holefill::viewer
