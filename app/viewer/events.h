// Window input as plain values: the window produces them, the interaction code consumes them,
// and neither side needs the other's library.
#pragma once

#include <algorithm>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace holefill::viewer {

enum class MouseButton { Left, Right, Middle };

struct InputEvent {
  enum class Kind { ButtonDown, ButtonUp, CursorMove, Scroll, Key, Drop };
  Kind kind = Kind::CursorMove;
  glm::vec2 cursor{0.0f};  // window pixels, top-left origin, at the time of the event
  MouseButton button = MouseButton::Left;
  float scroll = 0.0f;  // positive: away from the user
  int key = 0;          // an upper-case letter, or one of the Key codes below
  bool shift = false;
  bool control = false;
  std::string path;  // a dropped file
};

enum Key : int { kKeyEscape = 256, kKeyEnter = 257, kKeyDelete = 261, kKeyF1 = 290, kKeyF12 = 301 };

}  // namespace holefill::viewer

namespace holefill::viewer {

// The keys pressed during one frame, from the window's own events: Dear ImGui 1.86 (Debian 12)
// only samples whether a key is down once per frame, so a tap shorter than a frame (synthetic
// input, fast typists on a slow renderer) would be lost to the dialogs.
struct FrameKeys {
  std::vector<int> keys;
  bool pressed(int key) const { return std::find(keys.begin(), keys.end(), key) != keys.end(); }
};

}  // namespace holefill::viewer
