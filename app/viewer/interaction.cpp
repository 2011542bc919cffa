#include "interaction.h"

#include <algorithm>
#include <utility>

#include "scene_arrays.h"

namespace holefill::viewer {

std::vector<PickLoop> pick_loops(const Session& session) {
  std::vector<PickLoop> loops;
  for (const auto& hole : session.holes()) {
    loops.push_back({hole.id, boundary_points(session.mesh(), hole)});
  }
  return loops;
}

std::optional<int> hole_under_cursor(const Session& session, const Camera& camera,
                                     const SceneArea& area, const glm::vec2& cursor) {
  PickView view;
  view.view_projection = camera.projection() * camera.view();
  view.viewport_origin = area.origin;
  view.viewport_size = area.size;
  return pick_hole(pick_loops(session), view, cursor);
}

void fit_mesh(Camera& camera, const Session& session) {
  const Mesh& mesh = session.mesh();
  glm::vec3 lo(0.0f), hi(0.0f);
  bool first = true;
  for (const auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    const glm::vec3 q(p[0], p[1], p[2]);
    lo = first ? q : glm::min(lo, q);
    hi = first ? q : glm::max(hi, q);
    first = false;
  }
  camera.fit(lo, hi);
}

void frame_hole(Camera& camera, const Session& session, int hole_id) {
  if (hole_id < 0 || hole_id >= static_cast<int>(session.holes().size())) return;
  const Hole& hole = session.holes()[hole_id];
  const auto points = boundary_points(session.mesh(), hole);
  glm::vec3 center(0.0f);
  for (const auto& p : points) center += p;
  center /= static_cast<float>(std::max<std::size_t>(points.size(), 1));
  float radius = 0.0f;
  for (const auto& p : points) radius = std::max(radius, glm::length(p - center));
  camera.frame(center, hole_view_direction(session.mesh(), hole), 2.0f * radius);
}

std::vector<Request> Interaction::take_requests() { return std::exchange(requests_, {}); }

void Interaction::run(Command command, Camera& camera, Session& session) {
  switch (command) {
    case Command::Deselect:
      session.select(-1);
      break;
    case Command::Frame:
      if (session.selected() >= 0)
        frame_hole(camera, session, session.selected());
      else
        fit_mesh(camera, session);
      break;
    case Command::ResetView:
      camera.reset();
      break;
    default:
      requests_.push_back({command, {}});
  }
}

void Interaction::handle(const InputEvent& event, const SceneArea& scene, bool ui_wants_mouse,
                         bool ui_wants_keyboard, Camera& camera, Session& session) {
  // The comparison shows the scene twice, side by side: the camera then works in the half
  // under the cursor, and holes are picked in the list only (each half has its own mesh).
  const bool comparing = session.compare() && session.selected() >= 0;
  SceneArea area = scene;
  if (comparing) {
    area.size.x *= 0.5f;
    if (event.cursor.x >= area.origin.x + area.size.x) area.origin.x += area.size.x;
  }
  camera.set_viewport(area.size);
  const glm::vec2 local = event.cursor - area.origin;
  switch (event.kind) {
    case InputEvent::Kind::ButtonDown:
      if (ui_wants_mouse || !scene.contains(event.cursor)) return;
      press_ = last_ = event.cursor;
      drag_ = event.button != MouseButton::Left ? Drag::Pan
              : event.shift                     ? Drag::PendingToggle
                                                : Drag::Pending;
      break;
    case InputEvent::Kind::CursorMove:
      if (drag_ == Drag::Pending && glm::length(event.cursor - press_) > 3.0f) {
        drag_ = Drag::Orbit;
        camera.begin_orbit(press_ - area.origin);
      }
      if (drag_ == Drag::PendingToggle && glm::length(event.cursor - press_) > 3.0f) {
        drag_ = Drag::Pan;
      }
      if (drag_ == Drag::Orbit) camera.orbit_to(local);
      if (drag_ == Drag::Pan) camera.pan(event.cursor - last_);
      last_ = event.cursor;
      if (drag_ == Drag::None) {
        const bool over_scene = !comparing && !ui_wants_mouse && area.contains(event.cursor);
        const auto hole =
            over_scene ? hole_under_cursor(session, camera, area, event.cursor) : std::nullopt;
        hovered_ = hole.value_or(-1);
      }
      break;
    case InputEvent::Kind::ButtonUp:
      if ((drag_ == Drag::Pending || drag_ == Drag::PendingToggle) && !comparing) {
        if (const auto hole = hole_under_cursor(session, camera, area, event.cursor)) {
          if (drag_ == Drag::Pending)
            session.select(*hole);
          else
            session.toggle(*hole);
        }
      }
      drag_ = Drag::None;
      break;
    case InputEvent::Kind::Scroll:
      if (!ui_wants_mouse && scene.contains(event.cursor)) camera.zoom(event.scroll, local);
      break;
    case InputEvent::Kind::Key:
      // A screenshot is taken whatever has the keyboard, so dialogs can be shown too; the text
      // size changes whatever has it.
      if (const auto command = command_for_key(event.key, event.control, event.shift)) {
        if (!ui_wants_keyboard || works_anywhere(*command)) run(*command, camera, session);
      }
      break;
    case InputEvent::Kind::Drop:
      requests_.push_back({std::nullopt, event.path});
      break;
  }
}

}  // namespace holefill::viewer
