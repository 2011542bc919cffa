#include "shortcuts.h"

#include <algorithm>
#include <iterator>

#include "events.h"

namespace holefill::viewer {
namespace {

constexpr Shortcut kShortcuts[] = {
    {Command::Open, 'O', true, false, "Ctrl+O", "open a mesh"},
    {Command::Save, 'S', true, false, "Ctrl+S", "save (the first time: where to)"},
    {Command::SaveAs, 'S', true, true, "Ctrl+Shift+S", "save as"},
    {Command::Undo, 'Z', true, false, "Ctrl+Z", "undo"},
    {Command::Redo, 'Y', true, false, "Ctrl+Y", "redo"},
    {Command::Redo, 'Z', true, true, "Ctrl+Shift+Z", "redo"},
    {Command::Deselect, kKeyEscape, false, false, "Esc", "deselect the hole, close a dialog"},
    {Command::ResetHole, kKeyDelete, false, false, "Delete", "take the selected hole's patch out"},
    {Command::Frame, 'F', false, false, "F", "frame the selected hole (or the mesh)"},
    {Command::ResetView, 'R', false, false, "R", "reset the view"},
    {Command::FillSelected, 'F', false, true, "Shift+F", "fill the selected hole (every stage)"},
    {Command::FillAll, 'F', true, false, "Ctrl+F", "fill all holes (up to the edge limit)"},
    {Command::Bridge, 'B', false, false, "B", "bridge the two selected loops (shift-click)"},
    {Command::Help, kKeyF1, false, false, "F1", "this help"},
    {Command::Screenshot, kKeyF12, false, false, "F12", "save a screenshot"},
    {Command::ZoomIn, '+', true, false, "Ctrl+Plus, Ctrl+=", "larger text and panel"},
    {Command::ZoomIn, '+', true, true, nullptr, "the same where + takes Shift"},
    {Command::ZoomOut, '-', true, false, "Ctrl+Minus", "smaller text and panel"},
    {Command::ZoomReset, '0', true, false, "Ctrl+0", "text at the screen's own size"},
};

}  // namespace

std::span<const Shortcut> shortcuts() { return kShortcuts; }

bool works_anywhere(Command command) {
  return command == Command::Screenshot || command == Command::ZoomIn ||
         command == Command::ZoomOut || command == Command::ZoomReset;
}

const char* describe(Command command) {
  const auto found = std::find_if(std::begin(kShortcuts), std::end(kShortcuts),
                                  [&](const auto& s) { return s.command == command; });
  return found == std::end(kShortcuts) ? "" : found->what;
}

std::optional<Command> command_for_key(int key, bool control, bool shift) {
  const auto found = std::find_if(std::begin(kShortcuts), std::end(kShortcuts), [&](const auto& s) {
    return s.key == key && s.control == control && s.shift == shift;
  });
  if (found == std::end(kShortcuts)) return std::nullopt;
  return found->command;
}

}  // namespace holefill::viewer
