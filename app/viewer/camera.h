// The orbit camera: arcball rotation about a target, panning in the view plane, zooming toward
// the point under the cursor, fitting a bounding box, framing a point from a direction. Pure
// maths on GLM, no GL, so it can be tested and shared by both halves of the comparison view.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace holefill::viewer {

class Camera {
 public:
  // The drawable area in pixels; the aspect ratio of the projection follows it.
  void set_viewport(const glm::vec2& size);
  const glm::vec2& viewport() const { return viewport_; }

  glm::mat4 view() const;
  glm::mat4 projection() const;
  glm::vec3 eye() const;
  glm::vec3 target() const { return target_; }
  float distance() const { return distance_; }

  // Arcball: start a drag at `cursor` (pixels, top-left origin), then follow it.
  void begin_orbit(const glm::vec2& cursor);
  void orbit_to(const glm::vec2& cursor);

  // Moves the target so that the scene follows a cursor moved by `delta` pixels.
  void pan(const glm::vec2& delta);

  // Scroll `steps` (positive: closer); the point under `cursor` on the target's plane stays put.
  void zoom(float steps, const glm::vec2& cursor);

  // Frames the box from the current direction; remembers it for reset().
  void fit(const glm::vec3& lo, const glm::vec3& hi);

  // Back to the default direction, framing the last fitted box.
  void reset();

  // Looks at `center` from direction `from` (pointing from center toward the eye), so that a
  // sphere of `radius` fills the view.
  void frame(const glm::vec3& center, const glm::vec3& from, float radius);

  float vertical_fov() const { return fov_; }
  // The world length one pixel of the viewport spans at view depth 1 (at depth d: d times it),
  // so that shaders can size offsets in pixels wherever a point lies.
  float pixel_size_at_unit_depth() const;

 private:
  glm::vec3 arcball_point(const glm::vec2& cursor) const;
  float fitting_distance(float radius) const;

  glm::vec2 viewport_{1.0f, 1.0f};
  glm::vec3 target_{0.0f};
  float distance_ = 3.0f;
  glm::quat rotation_{1.0f, 0.0f, 0.0f, 0.0f};  // camera orientation in the world
  float fov_ = glm::radians(40.0f);
  glm::vec3 scene_center_{0.0f};
  float scene_radius_ = 1.0f;
  glm::quat drag_start_rotation_{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 drag_start_point_{0.0f, 0.0f, 1.0f};
};

}  // namespace holefill::viewer
