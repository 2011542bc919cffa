// File dialogs: the desktop's own through zenity or kdialog (as portable file dialog libraries
// do) when one is on PATH, else the viewer's in-app one (folder listing below). The native
// dialog is a separate process, so the caller runs it off the frame loop and polls for the
// answer. No GL and no ImGui.
#pragma once

#include <filesystem>
#include <future>
#include <optional>
#include <string>
#include <vector>

namespace holefill::viewer {

struct FileDialogRequest {
  enum class Kind { Open, Save };
  Kind kind = Kind::Open;
  // Open: the folder to start in. Save: the suggested file (its folder and name).
  std::filesystem::path start;
};

// "zenity" or "kdialog" when found on PATH (in that order), empty when neither is, or when the
// environment variable HOLEFILL_FILE_DIALOG is "builtin" (tests and users who prefer the
// in-app dialog).
std::string find_native_dialog_program();

// The argument vector that shows `request` with `program` ("zenity" or "kdialog"), filtering
// for the mesh formats the viewer reads (Open) or writes (Save). zenity's Save dialog confirms
// overwriting itself; kdialog's does too.
std::vector<std::string> native_dialog_command(const FileDialogRequest& request,
                                               const std::string& program);

// What a native dialog answered.
struct NativeDialogResult {
  bool ran = false;                             // false: it could not run (use the in-app dialog)
  std::optional<std::filesystem::path> chosen;  // nothing: the user cancelled
};

// Runs `command` (blocking until the dialog closes) and reads the chosen path from its output.
// Exit status 0 with a path: chosen; 1: cancelled; anything else, or no such program: not ran.
NativeDialogResult run_native_dialog(const std::vector<std::string>& command);

// A native dialog running on its own thread, so that the window keeps drawing meanwhile.
class NativeDialog {
 public:
  void start(std::vector<std::string> command);
  bool running() const { return result_.valid(); }
  // The answer once the dialog has closed (once), else nothing.
  std::optional<NativeDialogResult> poll();

 private:
  std::future<NativeDialogResult> result_;
};

// One entry of the in-app dialog's folder listing.
struct FolderEntry {
  std::string name;
  bool folder = false;
};

// The sub-folders and the files with one of `extensions` (lower case,
// with the dot; compared case-insensitively: holefill::lowercase_extension) in `folder`, folders
// first, each group sorted by name; hidden entries are left out. An unreadable folder gives an
// empty list.
std::vector<FolderEntry> list_folder(const std::filesystem::path& folder,
                                     const std::vector<std::string>& extensions);

}  // namespace holefill::viewer
