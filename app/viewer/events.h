// Window input as plain values: the window produces them, the interaction code consumes them,
// and neither side needs the other's library.
#pragma once

#include <glm/glm.hpp>
#include <string>

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

enum Key : int { kKeyEscape = 256, kKeyDelete = 261 };

}  // namespace holefill::viewer
