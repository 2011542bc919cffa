#include "camera.h"

#include <gtest/gtest.h>

#include "picking.h"

namespace holefill::viewer {
namespace {

PickView pick_view(const Camera& camera) {
  return {camera.projection() * camera.view(), glm::vec2(0.0f), camera.viewport()};
}

Camera fitted() {
  Camera camera;
  camera.set_viewport({800.0f, 600.0f});
  camera.fit({-1.0f, -2.0f, -1.0f}, {3.0f, 2.0f, 1.0f});
  return camera;
}

TEST(Camera, FitCentresTheBoxAndShowsAllOfIt) {
  const Camera camera = fitted();
  const auto centre = project_to_screen(pick_view(camera), {1.0f, 0.0f, 0.0f});
  ASSERT_TRUE(centre);
  EXPECT_NEAR(centre->x, 400.0f, 1e-2f);
  EXPECT_NEAR(centre->y, 300.0f, 1e-2f);
  for (float x : {-1.0f, 3.0f}) {
    for (float y : {-2.0f, 2.0f}) {
      for (float z : {-1.0f, 1.0f}) {
        const auto corner = project_to_screen(pick_view(camera), {x, y, z});
        ASSERT_TRUE(corner);
        EXPECT_GE(corner->x, 0.0f);
        EXPECT_LE(corner->x, 800.0f);
        EXPECT_GE(corner->y, 0.0f);
        EXPECT_LE(corner->y, 600.0f);
      }
    }
  }
}

TEST(Camera, ZoomKeepsThePointUnderTheCursorInPlace) {
  Camera camera = fitted();
  const glm::vec2 cursor{600.0f, 150.0f};
  // The world point under the cursor on the target's plane (z = 0 facing the default view).
  const float distance_before = camera.distance();
  const glm::vec3 under = [&] {
    const glm::mat4 inverse = glm::inverse(camera.projection() * camera.view());
    const glm::vec4 target_clip =
        camera.projection() * camera.view() * glm::vec4(camera.target(), 1.0f);
    const float ndc_z = target_clip.z / target_clip.w;
    const glm::vec4 p =
        inverse * glm::vec4(cursor.x / 400.0f - 1.0f, 1.0f - cursor.y / 300.0f, ndc_z, 1.0f);
    return glm::vec3(p) / p.w;
  }();
  camera.zoom(3.0f, cursor);
  EXPECT_LT(camera.distance(), distance_before);
  const auto after = project_to_screen(pick_view(camera), under);
  ASSERT_TRUE(after);
  EXPECT_NEAR(after->x, cursor.x, 0.5f);
  EXPECT_NEAR(after->y, cursor.y, 0.5f);
}

TEST(Camera, OrbitTurnsAboutTheTargetAndResetUndoesIt) {
  Camera camera = fitted();
  const glm::vec3 eye = camera.eye();
  camera.begin_orbit({400.0f, 300.0f});
  camera.orbit_to({550.0f, 300.0f});
  EXPECT_NEAR(glm::length(camera.eye() - camera.target()), camera.distance(), 1e-4f);
  // Dragging right brings the scene's right side toward the viewer: the eye moves to -x.
  EXPECT_LT(camera.eye().x, eye.x - 0.1f);
  camera.reset();
  EXPECT_NEAR(glm::length(camera.eye() - eye), 0.0f, 1e-4f);
}

TEST(Camera, PanMovesTheSceneWithTheCursor) {
  Camera camera = fitted();
  const glm::vec3 point{1.0f, 0.0f, 0.0f};
  const glm::vec2 before = glm::vec2(*project_to_screen(pick_view(camera), point));
  camera.pan({30.0f, -20.0f});
  const glm::vec2 after = glm::vec2(*project_to_screen(pick_view(camera), point));
  EXPECT_NEAR(after.x - before.x, 30.0f, 0.5f);
  EXPECT_NEAR(after.y - before.y, -20.0f, 0.5f);
}

TEST(Camera, FrameLooksAtThePointFromTheGivenSide) {
  Camera camera = fitted();
  camera.frame({1.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.5f);
  EXPECT_NEAR(glm::length(camera.target() - glm::vec3(1.0f, 1.0f, 0.0f)), 0.0f, 1e-5f);
  const glm::vec3 direction = glm::normalize(camera.eye() - camera.target());
  EXPECT_NEAR(direction.x, 1.0f, 1e-4f);
}

// The outline shader sizes its depth offset in pixels with this: a step of depth * size across
// the view direction, at any depth, moves a point one pixel on screen.
TEST(Camera, PixelSizeAtUnitDepthSpansOnePixelAtEveryDepth) {
  Camera camera = fitted();
  camera.frame({1.0f, 1.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, 0.5f);
  const glm::vec3 right = glm::normalize(glm::vec3(glm::inverse(camera.view())[0]));
  const glm::vec3 forward = glm::normalize(camera.target() - camera.eye());
  for (const float scale : {0.5f, 1.0f, 2.0f, 4.0f}) {
    const float depth = scale * camera.distance();
    const glm::vec3 point = camera.eye() + depth * forward;
    const glm::vec3 beside = point + depth * camera.pixel_size_at_unit_depth() * right;
    const auto a = project_to_screen(pick_view(camera), point);
    const auto b = project_to_screen(pick_view(camera), beside);
    ASSERT_TRUE(a && b);
    EXPECT_NEAR(glm::length(glm::vec2(*b) - glm::vec2(*a)), 1.0f, 1e-3f) << "at depth " << depth;
  }
}

}  // namespace
}  // namespace holefill::viewer
