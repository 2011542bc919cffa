// What mouse and keys do in the 3D view: left drag orbits (arcball), right or middle drag (or
// shift + left) pans, the wheel zooms toward the cursor, a left click picks a hole and a
// shift-click adds a loop to the selection or takes it out (islands, a hole to bridge to). Keys
// follow the shortcut table (shortcuts.h): those about the view and the selection (deselect, frame,
// reset view) are carried out here; those that change the mesh (undo, redo, reset hole, fills,
// which run on the worker), those about files, help and screenshots, and dropped files, are
// handed to the frame loop as requests. No GL: it moves the camera and calls the session.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "camera.h"
#include "events.h"
#include "picking.h"
#include "session.h"
#include "shortcuts.h"

namespace holefill::viewer {

// The part of the window the 3D view covers, in window pixels.
struct SceneArea {
  glm::vec2 origin{0.0f};
  glm::vec2 size{1.0f};
  bool contains(const glm::vec2& p) const {
    return p.x >= origin.x && p.y >= origin.y && p.x < origin.x + size.x && p.y < origin.y + size.y;
  }
};

// Every hole's boundary loop on the session's mesh, for picking.
std::vector<PickLoop> pick_loops(const Session& session);

// The hole under `cursor` (window pixels) as the camera sees it.
std::optional<int> hole_under_cursor(const Session& session, const Camera& camera,
                                     const SceneArea& area, const glm::vec2& cursor);

// Fits the camera to the whole mesh.
void fit_mesh(Camera& camera, const Session& session);
// Centres the camera on a hole, looking at it from outside the surface.
void frame_hole(Camera& camera, const Session& session, int hole_id);

// Something for the frame loop to do: a command of the shortcut table, or opening a dropped file
// (command nothing, path set).
struct Request {
  std::optional<Command> command;
  std::filesystem::path path;
};

class Interaction {
 public:
  // `ui_wants_mouse` / `ui_wants_keyboard`: the UI took the input (ImGui's WantCapture...).
  void handle(const InputEvent& event, const SceneArea& area, bool ui_wants_mouse,
              bool ui_wants_keyboard, Camera& camera, Session& session);
  int hovered() const { return hovered_; }
  // Whether a drag is turning or panning the camera (a big mesh is then drawn coarse).
  bool moving_camera() const { return drag_ == Drag::Orbit || drag_ == Drag::Pan; }
  // The requests since the last call, in order.
  std::vector<Request> take_requests();

 private:
  // Pending: a left press that picks on release unless it moves (then orbits); PendingToggle:
  // the same with shift, which adds or removes the loop (or pans when it moves).
  enum class Drag { None, Pending, PendingToggle, Orbit, Pan };
  Drag drag_ = Drag::None;
  glm::vec2 press_{0.0f};
  glm::vec2 last_{0.0f};
  int hovered_ = -1;
  std::vector<Request> requests_;

  void run(Command command, Camera& camera, Session& session);
};

}  // namespace holefill::viewer
