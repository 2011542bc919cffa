// holefill-viewer: open a mesh, see its holes, fill them stage by stage (issue #3).
// The frame loop is the one of Dear ImGui's GLFW + OpenGL 3 example: poll, new frame, build the
// UI, render the scene, render the UI, swap. Scripted mode (--screenshot) runs the requested
// actions first, renders a few frames, saves the PNG and exits.
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <epoxy/gl.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "background.h"
#include "camera.h"
#include "command_line.h"
#include "dialogs.h"
#include "file_actions.h"
#include "file_dialog.h"
#include "interaction.h"
#include "panels.h"
#include "renderer.h"
#include "screenshot.h"
#include "session.h"
#include "ui_style.h"
#include "window.h"
#include "worker.h"

namespace hv = holefill::viewer;

namespace {

// Past this many faces the wireframe covers the whole surface and costs most of the frame, so
// a freshly opened mesh starts without it (the checkbox turns it back on).
constexpr std::size_t kWireframeFaceLimit = 200'000;

void mesh_opened(hv::Camera& camera, const hv::Session& session, hv::UiState& ui) {
  hv::fit_mesh(camera, session);
  ui.display.wireframe = session.mesh().n_faces() <= kWireframeFaceLimit;
}

// Carries out the command line's actions on the session; false (with a message) on failure.
bool run_script(const hv::CommandLine& command, hv::Session& session) {
  if (command.remesh || command.fair) {
    holefill::FillOptions options = session.options();
    options.refine.remesh = options.refine.remesh || command.remesh;
    if (command.fair) {
      options.smooth.method = holefill::SmoothMethod::Fair;
      options.smooth.fair.order = command.fair_order;
    }
    session.set_options(options);
  }
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
  session.set_compare_mode(command.compare_smoothing ? hv::CompareMode::Smoothing
                                                     : hv::CompareMode::Weights);
  session.set_compare(command.compare);
  session.comparison();  // a script's screenshot shows it at once
  return true;
}

// Shows the file dialog the file actions ask for: the desktop's own (zenity, kdialog) on a
// thread of its own while the window keeps drawing, or, when there is none or it cannot run,
// the in-app one.
class FileDialogs {
 public:
  FileDialogs() : native_program_(hv::find_native_dialog_program()) {}
  bool builtin() const { return native_program_.empty(); }
  void update(hv::FileActions& files) {
    if (builtin()) return;
    if (files.dialog() && !native_.running()) {
      kind_ = files.dialog()->kind;
      native_.start(hv::native_dialog_command(*files.dialog(), native_program_));
    }
    const auto answer = native_.poll();
    if (!answer) return;
    if (!answer->ran) {
      std::fprintf(stderr, "holefill-viewer: %s did not run; using the in-app file dialog\n",
                   native_program_.c_str());
      native_program_.clear();
      return;
    }
    // zenity and kdialog ask before replacing a file themselves.
    files.dialog_closed(answer->chosen, kind_ == hv::FileDialogRequest::Kind::Save);
  }

 private:
  std::string native_program_;
  hv::NativeDialog native_;
  hv::FileDialogRequest::Kind kind_ = hv::FileDialogRequest::Kind::Open;
};

// Carries out what the interaction handed over: file commands, fills, help, screenshots, drops.
void carry_out(const hv::Request& request, hv::FileActions& files, hv::Session& session,
               hv::Worker& worker, hv::UiState& ui) {
  if (!request.command) {
    files.open_file(request.path);
    return;
  }
  switch (*request.command) {
    case hv::Command::Open:
      files.open();
      break;
    case hv::Command::Save:
      files.save();
      break;
    case hv::Command::SaveAs:
      files.save_as();
      break;
    case hv::Command::FillSelected:
      hv::start_fill(worker, session, session.fill_selected_request());
      break;
    case hv::Command::FillAll:
      hv::start_fill(worker, session,
                     session.fill_all_request(static_cast<std::size_t>(ui.fill_all_max_edges)));
      break;
    case hv::Command::Bridge:
      if (session.bridge_problem().empty())
        hv::start_fill(worker, session, session.fill_selected_request());
      else
        session.tell({session.bridge_problem(), true});
      break;
    case hv::Command::Undo:
      hv::start_change(worker, session, session.undo_request());
      break;
    case hv::Command::Redo:
      hv::start_change(worker, session, session.redo_request());
      break;
    case hv::Command::ResetHole:
      hv::start_change(worker, session, session.reset_request());
      break;
    case hv::Command::Help:
      ui.show_help = true;
      break;
    case hv::Command::Screenshot:
      ui.take_screenshot = true;
      break;
    case hv::Command::ZoomIn:
    case hv::Command::ZoomOut:
    case hv::Command::ZoomReset:
      ui.zoom = hv::zoom_after(ui.zoom, *request.command);
      session.tell({"Text size " + std::to_string(std::lround(100.0f * hv::zoom_factor(ui.zoom))) +
                        " % (Ctrl+Plus, Ctrl+Minus, Ctrl+0)",
                    false});
      break;
    default:
      break;
  }
}

hv::SceneArea scene_area(const hv::Window& window, const hv::UiScale& scale) {
  const glm::vec2 size = window.size();
  const float panel = std::min(scale.panel_width(), size.x - 1.0f);
  return {{panel, 0.0f}, {std::max(size.x - panel, 1.0f), size.y}};
}

// Draws the panel at the scale the monitor and the user's zoom ask for, when it changed.
void update_ui_scale(hv::UiState& ui) {
  const hv::UiScale wanted = hv::ui_scale(ui.content_scale, ui.zoom);
  if (wanted == ui.scale) return;
  ui.scale = wanted;
  hv::apply_ui_scale(wanted);
}

hv::PixelRect to_framebuffer(const hv::SceneArea& area, const hv::Window& window) {
  const glm::vec2 scale =
      glm::vec2(window.framebuffer_size()) / glm::max(glm::vec2(window.size()), 1.0f);
  return {static_cast<int>(area.origin.x * scale.x), static_cast<int>(area.origin.y * scale.y),
          static_cast<int>(area.size.x * scale.x), static_cast<int>(area.size.y * scale.y)};
}

void save_screenshot(const hv::Renderer& renderer, const hv::Window& window,
                     const std::filesystem::path& path) {
  const glm::ivec2 size = window.framebuffer_size();
  hv::write_png(path, size.x, size.y, renderer.read_pixels(size.x, size.y));
}

int run(const hv::CommandLine& command, const char* executable) {
  const auto started = std::chrono::steady_clock::now();
  hv::Session session;
  hv::FileActions files(session);
  hv::Worker worker;
  const auto mesh_path = command.mesh.empty() ? hv::default_mesh_path(executable) : command.mesh;
  const bool scripted = !command.screenshot.empty();
  // A plain start reads the mesh on the worker, so the window shows at once with a progress
  // bar; scripted actions need the mesh first.
  const bool read_first = scripted || command.select_hole || command.fill_all || command.remesh ||
                          command.fair || !command.save.empty();
  if (read_first && !files.open_now(mesh_path)) {
    std::fprintf(stderr, "holefill-viewer: %s\n", session.notice().text.c_str());
    return 3;
  }
  if (!run_script(command, session)) return 2;
  if (!command.save.empty() && !session.save(command.save)) {
    std::fprintf(stderr, "holefill-viewer: %s\n", session.notice().text.c_str());
    return 4;
  }
  if (!command.save.empty()) std::printf("%s\n", session.notice().text.c_str());
  if (!command.save.empty() && !scripted) return 0;

  hv::Window window(command.width, command.height, files.window_title().c_str());
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename =
      nullptr;  // the layout is fixed; no imgui.ini next to the user's files
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window.handle(), true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  hv::Renderer renderer;
  hv::Camera camera;
  hv::Interaction interaction;
  if (!read_first) hv::start_open(worker, session, files, mesh_path);
  files.open_with([&](const std::filesystem::path& path) {
    if (!hv::start_open(worker, session, files, path))
      session.tell({"Busy: wait for the work in progress or cancel it.", true});
  });
  hv::UiState ui;
  ui.content_scale = command.ui_scale > 0.0f ? command.ui_scale : window.content_scale();
  hv::apply_ui_scale(ui.scale = hv::ui_scale(ui.content_scale, ui.zoom));
  FileDialogs dialogs;
  hv::BuiltinDialog builtin_dialog;
  camera.set_viewport(scene_area(window, ui.scale).size);
  files.take_mesh_opened();
  mesh_opened(camera, session, ui);
  if (session.selected() >= 0) hv::frame_hole(camera, session, session.selected());

  int status = 0;
  std::string title = files.window_title();
  std::chrono::steady_clock::time_point timer_start;
  for (int frame = 0;; ++frame) {
    // The window manager's close button asks; unsaved fills keep the window open behind the
    // Save changes question. A scripted run closes itself.
    if (window.should_close()) {
      if (scripted) break;
      window.cancel_close();
      files.quit();
    }
    if (files.quitting()) break;
    if (worker.poll()) {
      if (!worker.error().empty()) session.tell({worker.error(), true});
      // A comparison cancelled (Esc) turns the comparison off rather than starting it again.
      if (worker.cancelled() && session.comparison_request()) session.set_compare(false);
      // A mesh named on the command line that cannot be read ends the program, as it does
      // without a window.
      if (files.opened_path().empty()) {
        std::fprintf(stderr, "holefill-viewer: %s\n", session.notice().text.c_str());
        status = 3;
        break;
      }
    }
    // The comparison is made on the worker too, whenever it is out of date and nothing runs.
    if (!scripted) hv::start_comparison(worker, session);
    const hv::SceneArea area = scene_area(window, ui.scale);
    camera.set_viewport(area.size);
    hv::FrameKeys keys;
    for (const auto& event : window.poll()) {
      if (event.kind == hv::InputEvent::Kind::Key) keys.keys.push_back(event.key);
      // While the worker computes from the session, nothing else may change it: the keys
      // (but F12) wait, the mouse still turns the view.
      interaction.handle(event, area, ImGui::GetIO().WantCaptureMouse || files.busy(),
                         ImGui::GetIO().WantCaptureKeyboard || files.busy() || worker.busy(),
                         camera, session);
    }
    for (const auto& request : interaction.take_requests())
      carry_out(request, files, session, worker, ui);
    dialogs.update(files);
    update_ui_scale(ui);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImGui::BeginDisabled(files.busy() && !dialogs.builtin());
    hv::draw_panels(session, files, worker, ui, static_cast<float>(window.size().y));
    ImGui::EndDisabled();
    hv::draw_progress(worker, keys, area.origin.x, area.origin.x + area.size.x,
                      area.origin.y + area.size.y);
    hv::draw_comparison_labels(session, area.origin.x, area.origin.x + area.size.x, area.origin.y);
    hv::draw_file_modals(files, builtin_dialog, dialogs.builtin(), keys);
    hv::draw_help(ui.show_help, keys);
    ImGui::Render();
    if (files.take_mesh_opened()) mesh_opened(camera, session, ui);
    if (files.window_title() != title) {
      title = files.window_title();
      window.set_title(title.c_str());
    }
    // The comparison frames its hole in each half as it starts or its hole changes.
    const int compared = session.compare() ? session.selected() : -1;
    if (compared >= 0 && compared != ui.compared_hole) ui.frame_selected = true;
    ui.compared_hole = compared;
    if (ui.fit_view) hv::fit_mesh(camera, session);
    if (ui.reset_view) camera.reset();
    if (ui.frame_selected) {
      camera.set_viewport(compared >= 0 ? area.size * glm::vec2(0.5f, 1.0f) : area.size);
      hv::frame_hole(camera, session, session.selected());
    }
    ui.fit_view = ui.reset_view = ui.frame_selected = false;

    const glm::ivec2 framebuffer = window.framebuffer_size();
    renderer.render(session, camera, to_framebuffer(area, window), framebuffer.x, framebuffer.y,
                    ui.display, interaction.hovered());
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

    if (ui.take_screenshot) {
      ui.take_screenshot = false;
      try {
        save_screenshot(renderer, window, ui.screenshot_path);
        const auto where = std::filesystem::absolute(ui.screenshot_path).string();
        std::printf("saved %s\n", where.c_str());
        session.tell({"Screenshot saved to " + where, false});
      } catch (const std::exception& error) {
        std::fprintf(stderr, "holefill-viewer: %s\n", error.what());
        session.tell({std::string("Could not save the screenshot: ") + error.what(), true});
      }
    }
    if (command.report_frame_time && frame == 0) {
      glFinish();
      const std::chrono::duration<double, std::milli> first =
          std::chrono::steady_clock::now() - started;
      std::printf("first frame: %.0f ms after start (reading the mesh included)\n", first.count());
    }
    if (command.report_frame_time && frame == 1) timer_start = std::chrono::steady_clock::now();
    if (command.report_frame_time && frame >= 1) {
      camera.begin_orbit(camera.viewport() * 0.5f);
      camera.orbit_to(camera.viewport() * 0.5f + glm::vec2(2.0f, 0.0f));
    }
    // ImGui lays windows out over its first frames; a few frames settle the picture.
    if (scripted && frame >= command.frames - 1) {
      if (command.report_frame_time) {
        glFinish();
        const std::chrono::duration<double, std::milli> spent =
            std::chrono::steady_clock::now() - timer_start;
        std::printf("frame time: %.1f ms mean over %d frames (%zu triangles)\n",
                    spent.count() / (frame - 1), frame - 1, session.mesh().n_faces());
      }
      try {
        save_screenshot(renderer, window, command.screenshot);
      } catch (const std::exception& error) {
        std::fprintf(stderr, "holefill-viewer: %s\n", error.what());
        status = 4;
      }
      window.request_close();
    }
    window.swap();
  }

  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  return status;
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
