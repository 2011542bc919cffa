#include "dialogs.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <initializer_list>
#include <system_error>
#include <utility>

#include "holefill/io.h"
#include "shortcuts.h"
#include "widgets.h"

namespace holefill::viewer {
namespace {

constexpr const char* kSaveChanges = "Save changes?";
constexpr const char* kOverwrite = "Replace the file?";
constexpr const char* kHelp = "Keyboard";

// Opens the named modal if it is not open yet and begins it, centred.
bool begin_modal(const char* name) {
  if (!ImGui::IsPopupOpen(name)) ImGui::OpenPopup(name);
  const ImVec2 centre = ImGui::GetMainViewport()->GetCenter();
  ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  return ImGui::BeginPopupModal(name, nullptr, ImGuiWindowFlags_AlwaysAutoResize);
}

// One button of a question, with the key that presses it.
struct Choice {
  const char* label;
  int key;
  FileActions::Answer answer;
};

// A modal question: two lines of text and a row of buttons; passes the answer on.
void question(const char* name, const std::string& what, const char* ask,
              std::initializer_list<Choice> choices, FileActions& files, const FrameKeys& keys) {
  if (!begin_modal(name)) return;
  ImGui::TextUnformatted(what.c_str());
  ImGui::TextUnformatted(ask);
  std::optional<FileActions::Answer> answer;
  bool first = true;
  for (const auto& choice : choices) {
    if (!std::exchange(first, false)) ImGui::SameLine();
    if (ImGui::Button(choice.label) || keys.pressed(choice.key)) answer = choice.answer;
  }
  if (answer) {
    ImGui::CloseCurrentPopup();
    files.answer(*answer);
  }
  ImGui::EndPopup();
}

void save_changes_question(FileActions& files, const FrameKeys& keys) {
  question(kSaveChanges, files.file_name() + " has unsaved fills.", "Save them before going on?",
           {{"Save (Enter)", kKeyEnter, FileActions::Answer::Save},
            {"Discard (D)", 'D', FileActions::Answer::Discard},
            {"Cancel (Esc)", kKeyEscape, FileActions::Answer::Cancel}},
           files, keys);
}

void overwrite_question(FileActions& files, const FrameKeys& keys) {
  question(kOverwrite, files.overwrite_path().string() + " already exists.",
           "Replace it with the filled mesh?",
           {{"Replace (Enter)", kKeyEnter, FileActions::Answer::Save},
            {"Cancel (Esc)", kKeyEscape, FileActions::Answer::Cancel}},
           files, keys);
}

void show_folder(BuiltinDialog& dialog, const std::filesystem::path& folder, bool save) {
  dialog.folder = folder;
  dialog.entries = list_folder(folder, save ? writable_extensions() : readable_extensions());
}

// The path field's text as a path: relative names are in the dialog's folder.
std::filesystem::path typed_path(const BuiltinDialog& dialog) {
  const std::filesystem::path typed(dialog.name);
  return typed.is_absolute() ? typed : dialog.folder / typed;
}

// Acts on the path field: a folder is entered, a file is the answer.
void accept(FileActions& files, BuiltinDialog& dialog, bool save) {
  if (dialog.name.empty()) return;
  const std::filesystem::path path = typed_path(dialog).lexically_normal();
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    show_folder(dialog, path, save);
    dialog.name.clear();
    return;
  }
  dialog.showing = false;
  ImGui::CloseCurrentPopup();
  files.dialog_closed(path, false);
}

void folder_listing(FileActions& files, BuiltinDialog& dialog, bool save) {
  ImGui::BeginChild("entries", ImVec2(scaled(520.0f), scaled(260.0f)), true);
  if (dialog.folder.has_parent_path() && dialog.folder != dialog.folder.root_path()) {
    if (ImGui::Selectable("[..]")) show_folder(dialog, dialog.folder.parent_path(), save);
  }
  std::optional<std::filesystem::path> enter;
  for (const auto& entry : dialog.entries) {
    const std::string label = entry.folder ? "[" + entry.name + "]" : entry.name;
    if (ImGui::Selectable(label.c_str(), !entry.folder && entry.name == dialog.name,
                          ImGuiSelectableFlags_AllowDoubleClick)) {
      if (entry.folder) {
        enter = dialog.folder / entry.name;
      } else {
        dialog.name = entry.name;
        if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) accept(files, dialog, save);
      }
    }
  }
  ImGui::EndChild();
  if (enter) show_folder(dialog, *enter, save);
}

void builtin_file_dialog(FileActions& files, BuiltinDialog& dialog, const FrameKeys& keys) {
  const FileDialogRequest& request = *files.dialog();
  const bool save = request.kind == FileDialogRequest::Kind::Save;
  if (!dialog.showing) {
    dialog.showing = true;
    show_folder(dialog, save ? request.start.parent_path() : request.start, save);
    dialog.name = save ? request.start.filename().string() : "";
  }
  if (!begin_modal(save ? "Save mesh as" : "Open mesh")) return;
  ImGui::TextDisabled("%s", dialog.folder.string().c_str());
  folder_listing(files, dialog, save);
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  ImGui::SetNextItemWidth(scaled(520.0f));
  ImGui::InputTextWithHint("##name", save ? "file name (.obj .off .ply .stl)" : "file name or path",
                           &dialog.name);
  if (ImGui::Button(save ? "Save (Enter)" : "Open (Enter)") || keys.pressed(kKeyEnter))
    accept(files, dialog, save);
  ImGui::SameLine();
  if (dialog.showing && (ImGui::Button("Cancel (Esc)") || keys.pressed(kKeyEscape))) {
    dialog.showing = false;
    ImGui::CloseCurrentPopup();
    files.dialog_closed(std::nullopt, false);
  }
  ImGui::EndPopup();
}

}  // namespace

void draw_file_modals(FileActions& files, BuiltinDialog& dialog, bool builtin,
                      const FrameKeys& keys) {
  switch (files.question()) {
    case FileActions::Question::SaveChanges:
      save_changes_question(files, keys);
      return;
    case FileActions::Question::Overwrite:
      overwrite_question(files, keys);
      return;
    case FileActions::Question::None:
      break;
  }
  if (files.dialog() && builtin) builtin_file_dialog(files, dialog, keys);
}

void draw_progress(Worker& worker, const FrameKeys& keys, float left, float right, float bottom) {
  if (!worker.busy()) return;
  const float width = std::min(scaled(420.0f), right - left - 20.0f);
  ImGui::SetNextWindowPos(ImVec2(0.5f * (left + right), bottom - 20.0f), ImGuiCond_Always,
                          ImVec2(0.5f, 1.0f));
  ImGui::SetNextWindowSize(ImVec2(width, 0.0f));
  ImGui::Begin("##progress", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
  const bool cancelling = worker.cancelling();
  const std::string phase = worker.phase();
  ImGui::Text("%s%s  %.1f s", worker.label().c_str(),
              cancelling ? ": cancelled, stopping (the mesh stays as it was)" : "...",
              worker.seconds());
  if (!cancelling && !phase.empty()) ImGui::TextDisabled("%s", phase.c_str());
  ImGui::ProgressBar(static_cast<float>(worker.fraction()), ImVec2(-1.0f, 0.0f));
  ImGui::BeginDisabled(cancelling);
  if (ImGui::Button("Cancel (Esc)") || keys.pressed(kKeyEscape)) worker.cancel();
  ImGui::EndDisabled();
  ImGui::End();
}

void draw_help(bool& showing, const FrameKeys& keys) {
  if (!showing) return;
  if (!begin_modal(kHelp)) return;
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
    for (const auto& shortcut : shortcuts()) {
      if (!shortcut.keys) continue;
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(shortcut.keys);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(shortcut.what);
    }
    ImGui::EndTable();
  }
  ImGui::TextDisabled("Mouse: left drag orbits, right drag pans, wheel zooms, click picks a hole.");
  // The F1 that opened the help is still down on its first frame.
  const bool f1 = keys.pressed(kKeyF1) && !ImGui::IsWindowAppearing();
  if (ImGui::Button("Close (Esc)") || keys.pressed(kKeyEscape) || f1) {
    showing = false;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

}  // namespace holefill::viewer
