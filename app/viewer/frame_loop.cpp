#include "frame_loop.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <epoxy/gl.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>

#include "background.h"
#include "camera.h"
#include "dialogs.h"
#include "file_dialog.h"
#include "frame_pacer.h"
#include "interaction.h"
#include "panels.h"
#include "renderer.h"
#include "request_queue.h"
#include "screenshot.h"
#include "state_report.h"
#include "ui_style.h"

namespace holefill::viewer {
namespace {

// Past this many faces the wireframe covers the whole surface and costs most of the frame, so
// a freshly opened mesh starts without it (the checkbox turns it back on).
constexpr std::size_t kWireframeFaceLimit = 200'000;

void mesh_opened(Camera& camera, const Session& session, UiState& ui) {
  fit_mesh(camera, session);
  ui.display.wireframe = session.mesh().n_faces() <= kWireframeFaceLimit;
}

// Dear ImGui's context and its GLFW and OpenGL 3 backends, for as long as the window lives.
class ImGuiBackends {
 public:
  explicit ImGuiBackends(Window& window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // the layout is fixed; no imgui.ini beside user files
    // The window draws on events only (FramePacer): a blinking cursor would need frames.
    ImGui::GetIO().ConfigInputTextCursorBlink = false;
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window.handle(), true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
  }
  ~ImGuiBackends() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  ImGuiBackends(const ImGuiBackends&) = delete;
  ImGuiBackends& operator=(const ImGuiBackends&) = delete;
};

// Shows the file dialog the file actions ask for: the desktop's own (zenity, kdialog) on a
// thread of its own while the window keeps drawing, or, when there is none or it cannot run,
// the in-app one.
class FileDialogs {
 public:
  FileDialogs() : native_program_(find_native_dialog_program()) {}
  bool builtin() const { return native_program_.empty(); }
  bool running() const { return native_.running(); }
  void update(FileActions& files) {
    if (builtin()) return;
    if (files.dialog() && !native_.running()) {
      kind_ = files.dialog()->kind;
      native_.start(native_dialog_command(*files.dialog(), native_program_));
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
    files.dialog_closed(answer->chosen, kind_ == FileDialogRequest::Kind::Save);
  }

 private:
  std::string native_program_;
  NativeDialog native_;
  FileDialogRequest::Kind kind_ = FileDialogRequest::Kind::Open;
};

// Carries out what the interaction handed over: file commands, fills, help, screenshots, drops.
void carry_out(const Request& request, FileActions& files, Session& session, Worker& worker,
               UiState& ui) {
  if (!request.command) {
    files.open_file(request.path);
    return;
  }
  switch (*request.command) {
    case Command::Open:
      files.open();
      break;
    case Command::Save:
      files.save();
      break;
    case Command::SaveAs:
      files.save_as();
      break;
    case Command::FillSelected:
      start_fill(worker, session, session.fill_selected_request());
      break;
    case Command::FillAll:
      start_fill(worker, session,
                 session.fill_all_request(static_cast<std::size_t>(ui.fill_all_max_edges)));
      break;
    case Command::Bridge:
      if (session.bridge_problem().empty())
        start_fill(worker, session, session.fill_selected_request());
      else
        session.tell({session.bridge_problem(), true});
      break;
    case Command::Undo:
      start_change(worker, session, session.undo_request());
      break;
    case Command::Redo:
      start_change(worker, session, session.redo_request());
      break;
    case Command::ResetHole:
      start_change(worker, session, session.reset_request());
      break;
    case Command::Help:
      ui.show_help = true;
      break;
    case Command::Screenshot:
      ui.take_screenshot = true;
      break;
    case Command::ZoomIn:
    case Command::ZoomOut:
    case Command::ZoomReset:
      ui.zoom = zoom_after(ui.zoom, *request.command);
      session.tell({"Text size " + std::to_string(std::lround(100.0f * zoom_factor(ui.zoom))) +
                        " % (Ctrl+Plus, Ctrl+Minus, Ctrl+0)",
                    false});
      break;
    default:
      break;
  }
}

SceneArea scene_area(const Window& window, const UiScale& scale) {
  const glm::vec2 size = window.size();
  const float panel = std::min(scale.panel_width(), size.x - 1.0f);
  return {{panel, 0.0f}, {std::max(size.x - panel, 1.0f), size.y}};
}

// Draws the panel at the scale the monitor and the user's zoom ask for, when it changed.
void update_ui_scale(UiState& ui) {
  const UiScale wanted = ui_scale(ui.content_scale, ui.zoom);
  if (wanted == ui.scale) return;
  ui.scale = wanted;
  apply_ui_scale(wanted);
}

PixelRect to_framebuffer(const SceneArea& area, const Window& window) {
  const glm::vec2 scale =
      glm::vec2(window.framebuffer_size()) / glm::max(glm::vec2(window.size()), 1.0f);
  return {static_cast<int>(area.origin.x * scale.x), static_cast<int>(area.origin.y * scale.y),
          static_cast<int>(area.size.x * scale.x), static_cast<int>(area.size.y * scale.y)};
}

void save_screenshot(const Renderer& renderer, const Window& window,
                     const std::filesystem::path& path) {
  const glm::ivec2 size = window.framebuffer_size();
  write_png(path, size.x, size.y, renderer.read_pixels(size.x, size.y));
}

// --frames' figures: the time from the start to the first frame on screen, then the mean frame
// time while the view keeps turning (so that every frame draws anew): the first half of the
// frames draw the whole mesh, the second half the coarse proxy that a drag draws.
class FrameTimer {
 public:
  FrameTimer(bool enabled, int frames, std::chrono::steady_clock::time_point started)
      : enabled_(enabled), split_(std::max(2, frames / 2)), started_(started) {}

  // Whether `frame` stands for one drawn while the camera is dragged.
  bool coarse(int frame) const { return enabled_ && frame > split_; }

  void frame_drawn(int frame, Camera& camera) {
    if (!enabled_) return;
    if (frame == 0) {
      glFinish();
      const std::chrono::duration<double, std::milli> first = Clock::now() - started_;
      std::printf("first frame: %.0f ms after start (reading the mesh included)\n", first.count());
    }
    if (frame == 1) timer_start_ = Clock::now();
    if (frame == split_) {
      glFinish();
      split_at_ = Clock::now();
    }
    if (frame >= 1) {
      camera.begin_orbit(camera.viewport() * 0.5f);
      camera.orbit_to(camera.viewport() * 0.5f + glm::vec2(2.0f, 0.0f));
    }
  }

  void report(int frame, std::size_t triangles, std::size_t proxy_triangles) const {
    if (!enabled_ || frame <= split_) return;
    glFinish();
    const std::chrono::duration<double, std::milli> whole = split_at_ - timer_start_;
    const std::chrono::duration<double, std::milli> coarse = Clock::now() - split_at_;
    std::printf("frame time: %.1f ms mean over %d frames (%zu triangles)\n",
                whole.count() / (split_ - 1), split_ - 1, triangles);
    std::printf("frame time while dragging: %.1f ms mean over %d frames (%s)\n",
                coarse.count() / (frame - split_), frame - split_,
                proxy_triangles
                    ? (std::to_string(proxy_triangles) + " triangles of the proxy").c_str()
                    : "no proxy: the whole mesh");
  }

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  int split_;
  Clock::time_point started_, timer_start_, split_at_;
};

// What the loop carries from frame to frame, and one step of it per method.
class FrameLoop {
 public:
  FrameLoop(const CommandLine& command, Window& window, Session& session, FileActions& files,
            Worker& worker, std::chrono::steady_clock::time_point started)
      : command_(command),
        scripted_(!command.screenshot.empty()),
        window_(window),
        session_(session),
        files_(files),
        worker_(worker),
        timer_(command.report_frame_time, command.frames, started),
        title_(files.window_title()),
        state_(command.state_file) {
    ui_.content_scale = command.ui_scale > 0.0f ? command.ui_scale : window.content_scale();
    apply_ui_scale(ui_.scale = ui_scale(ui_.content_scale, ui_.zoom));
    // A job that ends wakes the loop: its result (or its cancel) shows at once, not after the
    // pause between busy frames, which lasts a whole frame when frames are slow.
    worker_.set_on_done([] { Window::wake(); });
  }
  ~FrameLoop() { worker_.set_on_done({}); }  // the window goes before the worker's threads
  FrameLoop(const FrameLoop&) = delete;
  FrameLoop& operator=(const FrameLoop&) = delete;

  // Reads the mesh on the worker (when not read yet), routes dropped and chosen files there.
  void start(const std::filesystem::path& mesh_path, bool read_first) {
    if (!read_first) start_open(worker_, session_, files_, mesh_path);
    files_.open_with([this](const std::filesystem::path& path) {
      if (!start_open(worker_, session_, files_, path))
        session_.tell({"Busy: wait for the work in progress or cancel it.", true});
    });
    camera_.set_viewport(scene_area(window_, ui_.scale).size);
    files_.take_mesh_opened();
    mesh_opened(camera_, session_, ui_);
    if (session_.selected() >= 0) frame_hole(camera_, session_, session_.selected());
  }

  int run() {
    for (int frame = 0;; ++frame) {
      const auto frame_start = std::chrono::steady_clock::now();
      if (close_requested() || files_.quitting()) break;
      take_worker_result();
      // The comparison is made on the worker too, whenever it is out of date and nothing runs.
      if (!scripted_) start_comparison(worker_, session_);
      carry_out_waiting();
      const SceneArea area = scene_area(window_, ui_.scale);
      camera_.set_viewport(area.size);
      const FrameKeys keys = handle_input(area);
      draw_ui(area, keys);
      update_view(area);
      const glm::ivec2 framebuffer = window_.framebuffer_size();
      renderer_.render(session_, camera_, to_framebuffer(area, window_), framebuffer.x,
                       framebuffer.y, ui_.display, interaction_.hovered(),
                       interaction_.moving_camera() || timer_.coarse(frame));
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      take_requested_screenshot();
      timer_.frame_drawn(frame, camera_);
      // ImGui lays windows out over its first frames; a few frames settle the picture.
      if (scripted_ && frame >= command_.frames - 1) finish_script(frame);
      window_.swap();
      pacer_.frame_drawn(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - frame_start).count());
      report_state(frame + 1, false);
      wait_for_events(frame + 1);
    }
    return status_;
  }

 private:
  // The window manager's close button asks; unsaved fills keep the window open behind the
  // Save changes question. A scripted run closes itself. True: leave the loop.
  bool close_requested() {
    if (!window_.should_close()) return false;
    if (scripted_) return true;
    window_.cancel_close();
    files_.quit();
    return false;
  }

  // Takes what the worker finished. A mesh that could not be opened leaves the window open with
  // the reason in the status bar and Open at hand (from a desktop launcher there is no terminal
  // to read); the reason goes to stderr too.
  void take_worker_result() {
    if (!worker_.poll()) return;
    pacer_.wake();
    if (!worker_.error().empty()) session_.tell({worker_.error(), true});
    // A comparison cancelled (Esc) turns the comparison off rather than starting it again.
    if (worker_.cancelled() && session_.comparison_request()) session_.set_compare(false);
    cancel_told_ = false;
    if (files_.opened_path().empty() && session_.notice().error)
      std::fprintf(stderr, "holefill-viewer: %s\n", session_.notice().text.c_str());
  }

  FrameKeys handle_input(const SceneArea& area) {
    FrameKeys keys;
    const auto events = window_.poll();
    if (window_.polled_events()) pacer_.wake();
    for (const auto& event : events) {
      const bool key = event.kind == InputEvent::Kind::Key;
      if (key) keys.keys.push_back(event.key);
      // Esc while work runs cancels it (the progress box) rather than deselecting.
      if (key && event.key == kKeyEscape && worker_.busy()) continue;
      interaction_.handle(event, area, ImGui::GetIO().WantCaptureMouse || files_.busy(),
                          ImGui::GetIO().WantCaptureKeyboard || files_.busy(), camera_, session_);
    }
    for (const auto& request : interaction_.take_requests()) {
      // While the worker computes from the session nothing else may change it: what would
      // waits, in order, and is said to wait.
      if (waiting_.defer(request, worker_.busy())) {
        session_.tell({waiting_notice(request), false});
      } else {
        carry_out(request, files_, session_, worker_, ui_);
      }
    }
    dialogs_.update(files_);
    return keys;
  }

  void draw_ui(const SceneArea& area, const FrameKeys& keys) {
    update_ui_scale(ui_);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImGui::BeginDisabled(files_.busy() && !dialogs_.builtin());
    draw_panels(session_, files_, worker_, ui_, static_cast<float>(window_.size().y));
    ImGui::EndDisabled();
    const float left = area.origin.x, right = area.origin.x + area.size.x;
    draw_progress(worker_, keys, left, right, area.origin.y + area.size.y);
    draw_comparison_labels(session_, left, right, area.origin.y);
    draw_file_modals(files_, builtin_dialog_, dialogs_.builtin(), keys);
    draw_help(ui_.show_help, keys);
    ImGui::Render();
    // Esc stops the work at its next check; its result is dropped, so the mesh is unchanged
    // from this moment on: say so now, and drop what waited for it.
    if (worker_.cancelling() && !cancel_told_) {
      cancel_told_ = true;
      session_.tell({cancelled_notice(worker_), false});
      waiting_.clear();
    }
    if (files_.take_mesh_opened()) mesh_opened(camera_, session_, ui_);
    if (files_.window_title() != title_) {
      title_ = files_.window_title();
      window_.set_title(title_.c_str());
    }
  }

  // Something runs or waits: the frames go on (the progress moves, the queue empties).
  bool working() const { return worker_.busy() || dialogs_.running() || !waiting_.empty(); }

  // The first request that waited for the worker, once it is free.
  void carry_out_waiting() {
    if (files_.busy()) return;
    if (const auto request = waiting_.next(worker_.busy()))
      carry_out(*request, files_, session_, worker_, ui_);
  }

  // Sleeps in the window system until there is something to draw (FramePacer). A scripted run
  // and --frames draw every frame.
  void wait_for_events(int frames) {
    if (scripted_ || command_.report_frame_time) return;
    // A job that ended during the frame may have woken a wait that the frame's own event poll
    // took: its result is not to wait for the next pause.
    if (worker_.ended()) return;
    for (;;) {
      const auto wait = pacer_.wait_before_frame(working());
      if ((wait && *wait == 0.0) || window_.should_close()) return;
      if (!wait) report_state(frames, true);
      if (window_.wait(wait)) {
        pacer_.wake();
        return;
      }
      if (wait) return;  // work runs: its progress moves
    }
  }

  void report_state(int frames, bool idle) {
    ViewerState state;
    state.frames = frames;
    state.keys = window_.keys_received();
    state.closes = window_.close_requests();
    state.idle = idle;
    state.busy = worker_.busy();
    state.waiting = static_cast<int>(waiting_.size());
    state.question = files_.question() == FileActions::Question::SaveChanges ? "save-changes"
                     : files_.question() == FileActions::Question::Overwrite ? "overwrite"
                                                                             : "none";
    state.dialog = files_.dialog().has_value();
    state.title = title_;
    state.notice = session_.notice().text;
    state.phase = worker_.busy() ? worker_.phase() : "";
    state_.update(state);
  }

  // Moves the camera where the panel or the comparison asked.
  void update_view(const SceneArea& area) {
    // The comparison frames its hole in each half as it starts or its hole changes.
    const int compared = session_.compare() ? session_.selected() : -1;
    if (compared >= 0 && compared != ui_.compared_hole) ui_.frame_selected = true;
    ui_.compared_hole = compared;
    if (ui_.fit_view) fit_mesh(camera_, session_);
    if (ui_.reset_view) camera_.reset();
    if (ui_.frame_selected) {
      camera_.set_viewport(compared >= 0 ? area.size * glm::vec2(0.5f, 1.0f) : area.size);
      frame_hole(camera_, session_, session_.selected());
    }
    ui_.fit_view = ui_.reset_view = ui_.frame_selected = false;
  }

  // F12 or the panel's button: the window as a PNG, and a message saying where.
  void take_requested_screenshot() {
    if (!ui_.take_screenshot) return;
    ui_.take_screenshot = false;
    try {
      // Numbered rather than replacing an earlier one.
      const auto path = unused_path(ui_.screenshot_path);
      save_screenshot(renderer_, window_, path);
      const auto where = std::filesystem::absolute(path).string();
      std::printf("saved %s\n", where.c_str());
      session_.tell({"Screenshot saved to " + where, false});
    } catch (const std::exception& error) {
      std::fprintf(stderr, "holefill-viewer: %s\n", error.what());
      session_.tell({std::string("Could not save the screenshot: ") + error.what(), true});
    }
  }

  void finish_script(int frame) {
    timer_.report(frame, session_.mesh().n_faces(), renderer_.proxy_triangles());
    try {
      save_screenshot(renderer_, window_, command_.screenshot);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "holefill-viewer: %s\n", error.what());
      status_ = 4;
    }
    window_.request_close();
  }

  const CommandLine& command_;
  const bool scripted_;
  Window& window_;
  Session& session_;
  FileActions& files_;
  Worker& worker_;
  ImGuiBackends imgui_{window_};
  Renderer renderer_;
  Camera camera_;
  Interaction interaction_;
  UiState ui_;
  FileDialogs dialogs_;
  BuiltinDialog builtin_dialog_;
  FrameTimer timer_;
  std::string title_;
  FramePacer pacer_;
  StateReport state_;
  RequestQueue waiting_;
  bool cancel_told_ = false;  // the running job's cancel was announced
  int status_ = 0;
};

}  // namespace

int run_frames(const CommandLine& command, Window& window, Session& session, FileActions& files,
               Worker& worker, const std::filesystem::path& mesh_path, bool read_first,
               std::chrono::steady_clock::time_point started) {
  FrameLoop loop(command, window, session, files, worker, started);
  loop.start(mesh_path, read_first);
  return loop.run();
}

}  // namespace holefill::viewer
