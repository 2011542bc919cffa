#include "file_dialog.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <system_error>

#include "holefill/io.h"

extern char** environ;

namespace holefill::viewer {
namespace {

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::string folders = path;
  for (std::size_t start = 0; start <= folders.size();) {
    const std::size_t end = std::min(folders.find(':', start), folders.size());
    const auto candidate = std::filesystem::path(folders.substr(start, end - start)) / program;
    if (end > start && access(candidate.c_str(), X_OK) == 0) return true;
    start = end + 1;
  }
  return false;
}

// "*.obj *.OBJ *.off ..." for the given extensions.
std::string glob_patterns(const std::vector<std::string>& extensions) {
  std::string patterns;
  for (const auto& ext : extensions) {
    std::string upper = ext;
    std::transform(upper.begin(), upper.end(), upper.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    patterns += (patterns.empty() ? "*" : " *") + ext + " *" + upper;
  }
  return patterns;
}

}  // namespace

std::string find_native_dialog_program() {
  const char* choice = std::getenv("HOLEFILL_FILE_DIALOG");
  if (choice && std::string(choice) == "builtin") return {};
  for (const char* program : {"zenity", "kdialog"}) {
    if (on_path(program)) return program;
  }
  return {};
}

std::vector<std::string> native_dialog_command(const FileDialogRequest& request,
                                               const std::string& program) {
  const bool save = request.kind == FileDialogRequest::Kind::Save;
  const std::string patterns = glob_patterns(save ? writable_extensions() : readable_extensions());
  if (program == "kdialog") {
    return {program,
            save ? "--getsavefilename" : "--getopenfilename",
            request.start.string(),
            "Meshes (" + patterns + ")",
            "--title",
            save ? "Save mesh as" : "Open mesh"};
  }
  // zenity takes a folder with a trailing slash as "start here", a file as "select this".
  std::string start = request.start.string();
  if (!save && !start.empty() && start.back() != '/') start += '/';
  std::vector<std::string> command{program,
                                   "--file-selection",
                                   "--title",
                                   save ? "Save mesh as" : "Open mesh",
                                   "--filename=" + start,
                                   "--file-filter=Meshes | " + patterns,
                                   "--file-filter=All files | *"};
  if (save) {
    command.insert(command.begin() + 2, "--save");
    command.insert(command.begin() + 3, "--confirm-overwrite");
  }
  return command;
}

NativeDialogResult run_native_dialog(const std::vector<std::string>& command) {
  NativeDialogResult result;
  if (command.empty()) return result;
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) return result;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_ends[0]);
  std::vector<char*> argv;
  for (const auto& arg : command) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_ends[1]);
  std::string output;
  if (spawned == 0) {
    char buffer[4096];
    for (ssize_t n; (n = read(pipe_ends[0], buffer, sizeof buffer)) > 0;) output.append(buffer, n);
  }
  close(pipe_ends[0]);
  if (spawned != 0) return result;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status)) return result;
  const int code = WEXITSTATUS(status);
  // A child that could not exec the program exits with 127 (posix_spawnp may report it so).
  if (code != 0 && code != 1) return result;
  result.ran = true;
  while (!output.empty() && (output.back() == '\n' || output.back() == '\r')) output.pop_back();
  if (code == 0 && !output.empty()) result.chosen = std::filesystem::path(output);
  return result;
}

void NativeDialog::start(std::vector<std::string> command) {
  result_ = std::async(std::launch::async,
                       [command = std::move(command)] { return run_native_dialog(command); });
}

std::optional<NativeDialogResult> NativeDialog::poll() {
  if (!result_.valid() || result_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
    return std::nullopt;
  }
  return result_.get();
}

std::vector<FolderEntry> list_folder(const std::filesystem::path& folder,
                                     const std::vector<std::string>& extensions) {
  std::vector<FolderEntry> entries;
  std::error_code error;
  std::filesystem::directory_iterator it(folder, error), end;
  for (; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    std::error_code ignored;
    if (it->is_directory(ignored)) {
      entries.push_back({name, true});
    } else if (std::find(extensions.begin(), extensions.end(), lowercase_extension(it->path())) !=
               extensions.end()) {
      entries.push_back({name, false});
    }
  }
  std::sort(entries.begin(), entries.end(), [](const FolderEntry& a, const FolderEntry& b) {
    return a.folder != b.folder ? a.folder : a.name < b.name;
  });
  return entries;
}

}  // namespace holefill::viewer
