// What Open, Save, Save As, a dropped file and closing the window do to the user's work.
// Unsaved fills are never lost by surprise: those actions first ask "Save changes?" (Save,
// Discard, Cancel). Save never writes anywhere the user did not choose for the open mesh: the
// first Save of a mesh is a Save As, suggesting name-filled.ext beside the opened file, and
// opening another mesh forgets the previous target. Writing over an existing file is confirmed.
// No GL and no ImGui: the panels draw the dialog and the question this asks for; tests drive it.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>

#include "file_dialog.h"
#include "session.h"

namespace holefill::viewer {

// `wanted` when no file is there, else the first free "stem-2.ext", "stem-3.ext"... beside it:
// where a screenshot goes without replacing an earlier one.
std::filesystem::path unused_path(const std::filesystem::path& wanted);

class FileActions {
 public:
  enum class Question { None, SaveChanges, Overwrite };
  enum class Answer { Save, Discard, Cancel };  // Overwrite takes Save (yes) or Cancel

  explicit FileActions(Session& session) : session_(session) {}

  // Opens `path` now, without asking (the mesh named on the command line). False, with the
  // session's notice saying why, when it cannot be read.
  bool open_now(const std::filesystem::path& path);
  // From now on the Open dialog and dropped files call `open` instead of opening at once (the
  // viewer reads files on a worker); it must call opened() once the session holds the mesh.
  void open_with(std::function<void(const std::filesystem::path&)> open) {
    open_ = std::move(open);
  }
  // The session now holds the mesh read from `path`: Save forgets its target.
  void opened(const std::filesystem::path& path);

  // The user's requests. Each is ignored while a dialog or a question is showing.
  void open();                                        // the Open dialog
  void open_file(const std::filesystem::path& path);  // a dropped file
  void save();                                        // to the last Save As target, else Save As
  void save_as();                                     // the Save dialog
  // Closing the window: never ignored, also while a dialog or a question shows (it is dismissed;
  // the Save changes question then answers for closing).
  void quit();

  // The file dialog to show, if any; the frame loop shows it and reports with dialog_closed.
  const std::optional<FileDialogRequest>& dialog() const { return dialog_; }
  // `chosen`: nothing when cancelled. `overwrite_confirmed`: the dialog itself asked (zenity).
  void dialog_closed(const std::optional<std::filesystem::path>& chosen, bool overwrite_confirmed);

  Question question() const { return question_; }
  // The file the Overwrite question is about.
  const std::filesystem::path& overwrite_path() const { return overwrite_path_; }
  void answer(Answer answer);

  // True once the window may close: quit() was asked and nothing unsaved stood in the way.
  bool quitting() const { return quitting_; }
  // True once after a mesh was opened (the frame loop fits the view to it).
  bool take_mesh_opened();
  bool busy() const { return dialog_ || question_ != Question::None; }

  const std::filesystem::path& opened_path() const { return opened_; }
  // Where Save writes without asking: set by Save As, cleared by opening a mesh.
  const std::optional<std::filesystem::path>& save_target() const { return save_target_; }
  // What the Save dialog proposes: the save target, else name-filled.ext beside the opened file
  // (.obj when the opened format cannot be written).
  std::filesystem::path suggested_save_path() const;
  // The name of the file the work goes to: the save target, else the opened file.
  std::string file_name() const;
  // "*bunny.obj - holefill viewer": file_name(), a star when modified.
  std::string window_title() const;

 private:
  enum class Action { None, Quit, OpenDialog, OpenFile };

  void ask_or_do(Action action, const std::filesystem::path& path = {});
  void perform(Action action, const std::filesystem::path& path);
  void write(const std::filesystem::path& path);
  void continue_pending();
  void open_file_now_or_later(const std::filesystem::path& path);

  Session& session_;
  std::filesystem::path opened_;
  std::optional<std::filesystem::path> save_target_;
  std::optional<FileDialogRequest> dialog_;
  Question question_ = Question::None;
  std::filesystem::path overwrite_path_;
  Action pending_ = Action::None;  // waits behind the Save changes question or a save
  std::filesystem::path pending_path_;
  bool quitting_ = false;
  bool mesh_opened_ = false;
  std::function<void(const std::filesystem::path&)> open_;
};

}  // namespace holefill::viewer
