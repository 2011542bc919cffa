#include "file_actions.h"

#include <algorithm>
#include <optional>
#include <string>
#include <system_error>
#include <utility>

#include "holefill/mesh_format.h"

namespace holefill::viewer {
namespace {

// The extension a saved file gets when none was typed: the opened file's format's, else OBJ's.
std::string save_extension(const std::filesystem::path& opened) {
  const std::optional<MeshFormat> format = format_from_path(opened);
  return std::string(extension_of(format.value_or(MeshFormat::Obj)));
}

}  // namespace

std::filesystem::path unused_path(const std::filesystem::path& wanted) {
  std::error_code error;
  if (!std::filesystem::exists(wanted, error)) return wanted;
  for (int n = 2;; ++n) {
    auto candidate = wanted;
    candidate.replace_filename(wanted.stem().string() + "-" + std::to_string(n) +
                               wanted.extension().string());
    if (!std::filesystem::exists(candidate, error)) return candidate;
  }
}

bool FileActions::open_now(const std::filesystem::path& path) {
  if (!session_.open(path)) return false;
  opened(path);
  return true;
}

void FileActions::opened(const std::filesystem::path& path) {
  std::error_code error;
  opened_ = std::filesystem::absolute(path, error);
  if (error) opened_ = path;
  save_target_.reset();
  mesh_opened_ = true;
}

void FileActions::open_file_now_or_later(const std::filesystem::path& path) {
  if (open_)
    open_(path);
  else
    open_now(path);
}

void FileActions::open() { ask_or_do(Action::OpenDialog); }
void FileActions::open_file(const std::filesystem::path& path) {
  ask_or_do(Action::OpenFile, path);
}
void FileActions::quit() {
  // Never ignored: a file dialog or the overwrite question is dismissed; the Save changes
  // question, when it shows, now answers for closing.
  dialog_.reset();
  if (question_ == Question::Overwrite) question_ = Question::None;
  if (question_ == Question::SaveChanges) {
    pending_ = Action::Quit;
    return;
  }
  pending_ = Action::None;
  ask_or_do(Action::Quit);
}

void FileActions::save() {
  if (busy()) return;
  if (save_target_) {
    write(*save_target_);
  } else {
    save_as();
  }
}

void FileActions::save_as() {
  if (busy()) return;
  dialog_ = FileDialogRequest{FileDialogRequest::Kind::Save, suggested_save_path()};
}

void FileActions::dialog_closed(const std::optional<std::filesystem::path>& chosen,
                                bool overwrite_confirmed) {
  if (!dialog_) return;
  const FileDialogRequest request = *dialog_;
  dialog_.reset();
  if (!chosen) {
    pending_ = Action::None;  // a cancelled save also cancels what waited for it
    return;
  }
  if (request.kind == FileDialogRequest::Kind::Open) {
    open_file_now_or_later(*chosen);
    return;
  }
  std::filesystem::path path = *chosen;
  if (path.extension().empty()) path += save_extension(opened_);
  std::error_code error;
  if (!overwrite_confirmed && std::filesystem::exists(path, error)) {
    question_ = Question::Overwrite;
    overwrite_path_ = path;
    return;
  }
  write(path);
}

void FileActions::answer(Answer answer) {
  const Question question = question_;
  question_ = Question::None;
  if (question == Question::SaveChanges) {
    if (answer == Answer::Save) {
      save();
    } else if (answer == Answer::Discard) {
      continue_pending();
    } else {
      pending_ = Action::None;
    }
  } else if (question == Question::Overwrite) {
    if (answer == Answer::Save) {
      write(overwrite_path_);
    } else {
      // Back to the dialog, as desktop dialogs do, with the refused name to edit.
      dialog_ = FileDialogRequest{FileDialogRequest::Kind::Save, overwrite_path_};
    }
  }
}

bool FileActions::take_mesh_opened() {
  const bool opened = mesh_opened_;
  mesh_opened_ = false;
  return opened;
}

std::filesystem::path FileActions::suggested_save_path() const {
  if (save_target_) return *save_target_;
  const std::string stem = opened_.empty() ? "mesh" : opened_.stem().string();
  return opened_.parent_path() / (stem + "-filled" + save_extension(opened_));
}

std::string FileActions::file_name() const {
  const std::filesystem::path& file = save_target_ ? *save_target_ : opened_;
  return file.empty() ? "no mesh" : file.filename().string();
}

std::string FileActions::window_title() const {
  std::string title = session_.modified() ? "*" : "";
  title += file_name();
  title += " - holefill viewer";
  return title;
}

void FileActions::ask_or_do(Action action, const std::filesystem::path& path) {
  if (busy()) return;
  if (!session_.modified()) {
    perform(action, path);
    return;
  }
  pending_ = action;
  pending_path_ = path;
  question_ = Question::SaveChanges;
}

void FileActions::perform(Action action, const std::filesystem::path& path) {
  switch (action) {
    case Action::None:
      break;
    case Action::Quit:
      quitting_ = true;
      break;
    case Action::OpenDialog:
      dialog_ = FileDialogRequest{
          FileDialogRequest::Kind::Open,
          opened_.empty() ? std::filesystem::current_path() : opened_.parent_path()};
      break;
    case Action::OpenFile:
      open_file_now_or_later(path);
      break;
  }
}

void FileActions::write(const std::filesystem::path& path) {
  if (!session_.save(path)) {
    pending_ = Action::None;  // nothing that waited for the save goes ahead when it failed
    return;
  }
  save_target_ = path;
  continue_pending();
}

void FileActions::continue_pending() {
  const Action action = std::exchange(pending_, Action::None);
  perform(action, pending_path_);
}

}  // namespace holefill::viewer
