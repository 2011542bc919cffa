#include "picking.h"

#include <algorithm>
#include <limits>

namespace holefill::viewer {

std::optional<glm::vec3> project_to_screen(const PickView& view, const glm::vec3& point) {
  const glm::vec4 clip = view.view_projection * glm::vec4(point, 1.0f);
  if (clip.w <= 1e-6f) return std::nullopt;
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  const glm::vec2 pixel{(ndc.x * 0.5f + 0.5f) * view.viewport_size.x,
                        (0.5f - ndc.y * 0.5f) * view.viewport_size.y};
  return glm::vec3(view.viewport_origin + pixel, clip.w);
}

float distance_to_segment(const glm::vec2& p, const glm::vec2& a, const glm::vec2& b) {
  const glm::vec2 ab = b - a;
  const float length2 = glm::dot(ab, ab);
  const float t = length2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / length2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + t * ab));
}

bool polygon_contains(const std::vector<glm::vec2>& polygon, const glm::vec2& p) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const glm::vec2& a = polygon[i];
    const glm::vec2& b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) {
      inside = !inside;
    }
  }
  return inside;
}

std::optional<int> pick_hole(const std::vector<PickLoop>& loops, const PickView& view,
                             const glm::vec2& cursor, float tolerance_px) {
  std::optional<int> best;
  float best_distance = std::numeric_limits<float>::max();
  float best_depth = std::numeric_limits<float>::max();
  for (const auto& loop : loops) {
    if (loop.points.size() < 2) continue;
    std::vector<glm::vec2> polygon;
    std::vector<bool> visible;
    float depth = std::numeric_limits<float>::max();
    for (const auto& point : loop.points) {
      const auto screen = project_to_screen(view, point);
      visible.push_back(screen.has_value());
      polygon.push_back(screen ? glm::vec2(*screen) : glm::vec2(0.0f));
      if (screen) depth = std::min(depth, screen->z);
    }
    float distance = std::numeric_limits<float>::max();
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      if (visible[i] && visible[j]) {
        distance = std::min(distance, distance_to_segment(cursor, polygon[i], polygon[j]));
      }
    }
    const bool all_visible = std::all_of(visible.begin(), visible.end(), [](bool v) { return v; });
    if (all_visible && polygon_contains(polygon, cursor)) distance = 0.0f;
    if (distance > tolerance_px) continue;
    const bool clearly_closer = distance < best_distance - 0.5f;
    const bool tie_but_nearer = distance <= best_distance + 0.5f && depth < best_depth;
    if (!best || clearly_closer || tie_but_nearer) {
      best = loop.hole_id;
      best_distance = distance;
      best_depth = depth;
    }
  }
  return best;
}

}  // namespace holefill::viewer
