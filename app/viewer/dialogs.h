// The ImGui modals of the file actions: "Save changes?", "Replace the file?", the in-app file
// dialog (a folder listing and a path field, for desktops without zenity or kdialog), and the
// keyboard help (F1), and the progress of work on the worker. The buttons carry their keys: Enter,
// D(iscard), Esc.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "events.h"
#include "file_actions.h"
#include "file_dialog.h"
#include "worker.h"

namespace holefill::viewer {

// The in-app file dialog's state between frames.
struct BuiltinDialog {
  bool showing = false;
  std::filesystem::path folder;
  std::string name;  // the path field: a name in `folder`, or a path
  std::vector<FolderEntry> entries;
};

// Draws the question or the in-app dialog the file actions wait for, and passes on the answer.
// `builtin`: whether dialogs are the in-app one (else a native dialog is showing).
void draw_file_modals(FileActions& files, BuiltinDialog& dialog, bool builtin,
                      const FrameKeys& keys);

// While the worker is busy: what it does, a progress bar, the time spent, and Cancel (Esc), in a
// box at the bottom of the 3D view (from x = `left` to `right`, above `bottom`).
void draw_progress(Worker& worker, const FrameKeys& keys, float left, float right, float bottom);

// Draws the keyboard help while `showing`; Esc, F1 or the button close it.
void draw_help(bool& showing, const FrameKeys& keys);

}  // namespace holefill::viewer
