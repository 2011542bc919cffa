#include "camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace holefill::viewer {

void Camera::set_viewport(const glm::vec2& size) { viewport_ = glm::max(size, glm::vec2(1.0f)); }

glm::mat4 Camera::view() const {
  const glm::mat4 orientation = glm::mat4_cast(glm::conjugate(rotation_));
  return glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -distance_)) * orientation *
         glm::translate(glm::mat4(1.0f), -target_);
}

glm::mat4 Camera::projection() const {
  // Near and far follow the scene so that depth precision holds both zoomed in and out.
  const float far_plane = distance_ + 3.0f * scene_radius_;
  const float near_plane = std::max(far_plane * 1e-4f, distance_ - 3.0f * scene_radius_);
  return glm::perspective(fov_, viewport_.x / viewport_.y, near_plane, far_plane);
}

float Camera::pixel_size_at_unit_depth() const {
  return 2.0f * std::tan(0.5f * fov_) / viewport_.y;
}

glm::vec3 Camera::eye() const { return target_ + rotation_ * glm::vec3(0.0f, 0.0f, distance_); }

glm::vec3 Camera::arcball_point(const glm::vec2& cursor) const {
  // The cursor on a unit sphere spanning the smaller viewport side; outside it, a hyperbolic
  // sheet continues smoothly so that drags beyond the sphere still rotate.
  const float scale = 0.5f * std::min(viewport_.x, viewport_.y);
  const glm::vec2 p{(cursor.x - 0.5f * viewport_.x) / scale,
                    (0.5f * viewport_.y - cursor.y) / scale};
  const float r2 = glm::dot(p, p);
  const float z = r2 <= 0.5f ? std::sqrt(1.0f - r2) : 0.5f / std::sqrt(r2);
  return glm::normalize(glm::vec3(p, z));
}

void Camera::begin_orbit(const glm::vec2& cursor) {
  drag_start_rotation_ = rotation_;
  drag_start_point_ = arcball_point(cursor);
}

void Camera::orbit_to(const glm::vec2& cursor) {
  const glm::vec3 to = arcball_point(cursor);
  const float cos_angle = std::clamp(glm::dot(drag_start_point_, to), -1.0f, 1.0f);
  const glm::vec3 axis = glm::cross(drag_start_point_, to);
  if (glm::length(axis) < 1e-7f) return;
  // The drag turns the scene by q in camera space, so the camera turns by q's inverse.
  const glm::quat q = glm::angleAxis(std::acos(cos_angle), glm::normalize(axis));
  rotation_ = glm::normalize(drag_start_rotation_ * glm::conjugate(q));
}

void Camera::pan(const glm::vec2& delta) {
  const float world_per_pixel = 2.0f * distance_ * std::tan(0.5f * fov_) / viewport_.y;
  const glm::vec3 right = rotation_ * glm::vec3(1.0f, 0.0f, 0.0f);
  const glm::vec3 up = rotation_ * glm::vec3(0.0f, 1.0f, 0.0f);
  target_ += world_per_pixel * (-delta.x * right + delta.y * up);
}

void Camera::zoom(float steps, const glm::vec2& cursor) {
  const float factor = std::pow(0.85f, steps);
  const float world_per_pixel = 2.0f * distance_ * std::tan(0.5f * fov_) / viewport_.y;
  const glm::vec3 right = rotation_ * glm::vec3(1.0f, 0.0f, 0.0f);
  const glm::vec3 up = rotation_ * glm::vec3(0.0f, 1.0f, 0.0f);
  const glm::vec2 offset = cursor - 0.5f * viewport_;
  const glm::vec3 under_cursor = target_ + world_per_pixel * (offset.x * right - offset.y * up);
  target_ += (under_cursor - target_) * (1.0f - factor);
  distance_ = std::max(distance_ * factor, 1e-4f * scene_radius_);
}

float Camera::fitting_distance(float radius) const {
  const float aspect = viewport_.x / viewport_.y;
  const float half_fov = 0.5f * std::min(fov_, 2.0f * std::atan(std::tan(0.5f * fov_) * aspect));
  return radius / std::sin(half_fov);
}

void Camera::fit(const glm::vec3& lo, const glm::vec3& hi) {
  scene_center_ = 0.5f * (lo + hi);
  scene_radius_ = std::max(0.5f * glm::length(hi - lo), 1e-6f);
  target_ = scene_center_;
  distance_ = fitting_distance(scene_radius_);
}

void Camera::reset() {
  rotation_ = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
  target_ = scene_center_;
  distance_ = fitting_distance(scene_radius_);
}

void Camera::frame(const glm::vec3& center, const glm::vec3& from, float radius) {
  target_ = center;
  distance_ = fitting_distance(std::max(radius, 1e-6f));
  const glm::vec3 back = glm::normalize(from);
  // Keep the world's +y up unless the view looks straight along it.
  glm::vec3 up_hint = std::abs(back.y) > 0.95f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0, 1, 0);
  const glm::vec3 right = glm::normalize(glm::cross(up_hint, back));
  const glm::vec3 up = glm::cross(back, right);
  rotation_ = glm::normalize(glm::quat_cast(glm::mat3(right, up, back)));
}

}  // namespace holefill::viewer
