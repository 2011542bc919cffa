// The ImGui modals of the file actions: "Save changes?", "Replace the file?", the in-app file
// dialog (a folder listing and a path field, for desktops without zenity or kdialog), and the
// keyboard help (F1). The buttons carry their keys: Enter, D(iscard), Esc.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "events.h"
#include "file_actions.h"
#include "file_dialog.h"

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

// Draws the keyboard help while `showing`; Esc, F1 or the button close it.
void draw_help(bool& showing, const FrameKeys& keys);

}  // namespace holefill::viewer
