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
};

struct Shortcut {
  Command command;
  int key;  // an upper-case letter or a Key code (events.h)
  bool control = false;
  bool shift = false;
  const char* keys;  // as the help shows it
  const char* what;
};

std::span<const Shortcut> shortcuts();

// The command bound to `key` with these modifiers, if any.
std::optional<Command> command_for_key(int key, bool control, bool shift);

}  // namespace holefill::viewer
