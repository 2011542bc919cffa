// Screen-space hole picking: each hole's boundary loop is projected with the camera's matrices,
// and a click picks the hole whose projected polygon contains it or whose projected boundary
// passes within a few pixels. Working in screen space (not ray-surface hits) keeps picking
// reliable when a hole is seen edge-on, where its polygon collapses to a line. No GL here.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <vector>

namespace holefill::viewer {

struct PickLoop {
  int hole_id = -1;
  std::vector<glm::vec3> points;  // the boundary loop P0 ... Pn-1, world coordinates
};

struct PickView {
  glm::mat4 view_projection{1.0f};
  glm::vec2 viewport_origin{0.0f};  // top-left corner, in the same pixels as the cursor
  glm::vec2 viewport_size{1.0f};
};

// A world point on screen: pixels from the top-left corner, and its depth (clip w, the distance
// along the view direction). Nothing when the point is behind the camera.
std::optional<glm::vec3> project_to_screen(const PickView& view, const glm::vec3& point);

// Distance in pixels from `p` to the segment [a, b].
float distance_to_segment(const glm::vec2& p, const glm::vec2& a, const glm::vec2& b);

// Even-odd test of `p` against the closed polygon.
bool polygon_contains(const std::vector<glm::vec2>& polygon, const glm::vec2& p);

// The hole under the cursor: among loops whose projection contains the cursor (distance 0) or
// passes within tolerance_px of it, the smallest screen distance wins; ties (within half a
// pixel) go to the loop nearest the camera. Segments with a point behind the camera are skipped.
std::optional<int> pick_hole(const std::vector<PickLoop>& loops, const PickView& view,
                             const glm::vec2& cursor, float tolerance_px = 6.0f);

}  // namespace holefill::viewer
