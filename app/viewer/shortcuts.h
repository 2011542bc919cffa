// The viewer's keyboard shortcuts in one table: the interaction looks keys up in it and the help
// overlay (F1) lists it, so the two cannot disagree. No GL.
#pragma once

#include <optional>
#include <span>

namespace holefill::viewer {

enum class Command {
  Open,
  Save,
  SaveAs,
  Undo,
  Redo,
  Deselect,
  ResetHole,
  Frame,
  ResetView,
  FillSelected,
  FillAll,
  Bridge,
  Help,
  Screenshot,
  ZoomIn,     // the panel's text larger
  ZoomOut,    // smaller
  ZoomReset,  // the monitor's own size
};

struct Shortcut {
  Command command;
  int key;  // an upper-case letter or a Key code (events.h)
  bool control = false;
  bool shift = false;
  const char* keys;  // as the help shows it; nullptr: not listed (a variant of the line above)
  const char* what;
};

std::span<const Shortcut> shortcuts();

// Whether `command` works whatever has the keyboard (a text field, a dialog): screenshots and
// the text size.
bool works_anywhere(Command command);

// What `command` does, as the help says it ("undo", "fill all holes (up to the edge limit)").
const char* describe(Command command);

// The command bound to `key` with these modifiers, if any.
std::optional<Command> command_for_key(int key, bool control, bool shift);

}  // namespace holefill::viewer
