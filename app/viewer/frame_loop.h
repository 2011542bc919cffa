// The window's frame loop, as in Dear ImGui's GLFW + OpenGL 3 example: poll, new frame, build the
// UI, render the scene, render the UI, swap. Each frame takes the worker's finished work, the
// user's input and requests, draws, and, in a scripted run (--screenshot), saves the picture after
// a few frames and closes.
#pragma once

#include <chrono>
#include <filesystem>

#include "command_line.h"
#include "file_actions.h"
#include "session.h"
#include "window.h"
#include "worker.h"

namespace holefill::viewer {

// Opens Dear ImGui on `window` and runs frames until the user quits (or a scripted run is done).
// When `read_first` is false the mesh at `mesh_path` is read on the worker while the window shows
// (when it cannot be read, the window says why and offers Open). Returns the program's exit
// status: 0, or 4 when the scripted screenshot cannot be written.
int run_frames(const CommandLine& command, Window& window, Session& session, FileActions& files,
               Worker& worker, const std::filesystem::path& mesh_path, bool read_first,
               std::chrono::steady_clock::time_point started);

}  // namespace holefill::viewer
