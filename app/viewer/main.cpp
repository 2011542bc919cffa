// holefill-viewer: open a mesh, see its holes, fill them stage by stage. This file reads the
// command line and runs what it asks that needs no window (scripted actions, --save); the window's
// frames are frame_loop.h's. Scripted mode (--screenshot) runs the requested actions first,
// renders a few frames, saves the PNG and exits.
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "command_line.h"
#include "file_actions.h"
#include "frame_loop.h"
#include "session.h"
#include "window.h"
#include "worker.h"

namespace hv = holefill::viewer;

namespace {

// Carries out the command line's actions on the session; false (with a message) on failure.
bool run_script(const hv::CommandLine& command, hv::Session& session) {
  holefill::FillOptions options = session.options();
  options.refine.remesh = options.refine.remesh || command.remesh;
  if (command.fair) {
    options.smooth.method = holefill::SmoothMethod::Fair;
    options.smooth.fair.order = command.fair_order;
  }
  options.features.angle_degrees = command.feature_angle;
  if (options != session.options()) session.set_options(options);
  if (command.select_hole) {
    if (*command.select_hole < 0 ||
        *command.select_hole >= static_cast<int>(session.holes().size())) {
      std::fprintf(stderr, "holefill-viewer: --select-hole %d: the mesh has %zu holes\n",
                   *command.select_hole, session.holes().size());
      return false;
    }
    session.select(*command.select_hole);
  }
  for (const int hole : command.add_holes) {
    if (hole < 0 || hole >= static_cast<int>(session.holes().size()) || !session.toggle(hole)) {
      std::fprintf(stderr, "holefill-viewer: --add-hole %d: not a loop that can be added (%s)\n",
                   hole, session.notice().text.c_str());
      return false;
    }
  }
  for (const auto stage : command.run) {
    if (!session.step(stage)) {
      std::fprintf(stderr, "holefill-viewer: cannot run %s on hole %d%s%s\n",
                   holefill::to_string(stage), session.selected(),
                   session.notice().error ? ": " : " (stages run in order)",
                   session.notice().error ? session.notice().text.c_str() : "");
      return false;
    }
  }
  if (command.fill_all) session.fill_all();
  session.set_compare_triangulation_only(command.compare_triangulation_only);
  session.set_compare_mode(command.compare_smoothing  ? hv::CompareMode::Smoothing
                           : command.compare_features ? hv::CompareMode::Features
                                                      : hv::CompareMode::Weights);
  session.set_compare(command.compare);
  session.comparison();  // a script's screenshot shows it at once
  return true;
}

// The command line's work that needs no window: the mesh read first when scripted actions need
// it, those actions, --save. Returns the exit status when the program is done without a window
// (or failed), nothing when the window is to open.
std::optional<int> run_without_window(const hv::CommandLine& command, hv::Session& session,
                                      hv::FileActions& files,
                                      const std::filesystem::path& mesh_path, bool read_first) {
  if (read_first && !files.open_now(mesh_path)) {
    std::fprintf(stderr, "holefill-viewer: %s\n", session.notice().text.c_str());
    return 3;
  }
  if (!run_script(command, session)) return 2;
  if (command.save.empty()) return std::nullopt;
  if (!session.save(command.save)) {
    std::fprintf(stderr, "holefill-viewer: %s\n", session.notice().text.c_str());
    return 4;
  }
  std::printf("%s\n", session.notice().text.c_str());
  return command.screenshot.empty() ? std::optional<int>(0) : std::nullopt;
}

int run(const hv::CommandLine& command, const char* executable) {
  const auto started = std::chrono::steady_clock::now();
  hv::Session session;
  session.set_threads(command.threads);
  hv::FileActions files(session);
  hv::Worker worker;
  const auto mesh_path = command.mesh.empty() ? hv::default_mesh_path(executable) : command.mesh;
  // A plain start reads the mesh on the worker, so the window shows at once with a progress
  // bar; scripted actions need the mesh first.
  const bool read_first = !command.screenshot.empty() || command.select_hole || command.fill_all ||
                          command.remesh || command.fair || !command.save.empty() ||
                          command.feature_angle != holefill::FeatureOptions{}.angle_degrees;
  if (const auto status = run_without_window(command, session, files, mesh_path, read_first)) {
    return *status;
  }
  hv::Window window(command.width, command.height, files.window_title().c_str());
  return hv::run_frames(command, window, session, files, worker, mesh_path, read_first, started);
}

// This program's file: /proc/self/exe where the system has it (argv[0] may be a bare name found
// through PATH), else argv[0].
std::filesystem::path executable_path(const char* argv0) {
  std::error_code error;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::filesystem::path(argv0) : self;
}

}  // namespace

int main(int argc, char** argv) {
  hv::CommandLine command;
  try {
    command = hv::parse_command_line(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const std::exception& error) {
    std::fprintf(stderr, "holefill-viewer: %s\n(--help lists the options)\n", error.what());
    return 2;
  }
  if (command.help || command.version) {
    std::puts((command.help ? hv::usage() : hv::version()).c_str());
    return 0;
  }
  try {
    return run(command, executable_path(argv[0]).c_str());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "holefill-viewer: %s\n", error.what());
    return 1;
  }
}
