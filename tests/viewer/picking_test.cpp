#include "picking.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace holefill::viewer {
namespace {

// A circle of radius r around `center` in the plane spanned by u and v.
PickLoop circle(int id, glm::vec3 center, float r, glm::vec3 u = {1, 0, 0}, glm::vec3 v = {0, 1, 0},
                int n = 32) {
  PickLoop loop{id, {}};
  for (int i = 0; i < n; ++i) {
    const float a = 6.2831853f * static_cast<float>(i) / static_cast<float>(n);
    loop.points.push_back(center + r * (std::cos(a) * u + std::sin(a) * v));
  }
  return loop;
}

// A 800x600 view from `eye` toward the origin.
PickView view_from(glm::vec3 eye) {
  PickView view;
  view.viewport_size = {800.0f, 600.0f};
  view.view_projection = glm::perspective(glm::radians(40.0f), 800.0f / 600.0f, 0.01f, 100.0f) *
                         glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 1, 0));
  return view;
}

glm::vec2 screen(const PickView& view, glm::vec3 p) {
  return glm::vec2(*project_to_screen(view, p));
}

TEST(Picking, ProjectsTheLookAtPointToTheViewportCentreTopLeftOrigin) {
  PickView view = view_from({0, 0, 5});
  view.viewport_origin = {100.0f, 20.0f};
  const auto centre = project_to_screen(view, {0, 0, 0});
  ASSERT_TRUE(centre);
  EXPECT_NEAR(centre->x, 500.0f, 1e-3f);
  EXPECT_NEAR(centre->y, 320.0f, 1e-3f);
  EXPECT_NEAR(centre->z, 5.0f, 1e-4f);
  EXPECT_LT(screen(view, {0, 1, 0}).y, 320.0f);       // up in the world is up on the screen
  EXPECT_FALSE(project_to_screen(view, {0, 0, 10}));  // behind the camera
}

TEST(Picking, AClickInsideTheProjectedLoopPicksIt) {
  const PickView view = view_from({0, 0, 5});
  const std::vector<PickLoop> loops = {circle(7, {0, 0, 0}, 1.0f)};
  EXPECT_EQ(pick_hole(loops, view, screen(view, {0.3f, -0.2f, 0.0f})), 7);
}

TEST(Picking, AClickNearTheBoundaryOutsidePicksItAndFarAwayPicksNothing) {
  const PickView view = view_from({0, 0, 5});
  const std::vector<PickLoop> loops = {circle(3, {0, 0, 0}, 1.0f)};
  const glm::vec2 rim = screen(view, {1.0f, 0.0f, 0.0f});
  EXPECT_EQ(pick_hole(loops, view, rim + glm::vec2(4.0f, 0.0f)), 3);
  EXPECT_FALSE(pick_hole(loops, view, rim + glm::vec2(12.0f, 0.0f)));
  EXPECT_FALSE(pick_hole(loops, view, {5.0f, 5.0f}));
}

TEST(Picking, WorksWhenTheHoleIsSeenEdgeOn) {
  // The loop lies in the plane z = 0 and the eye is almost in that plane: its projection is a
  // sliver a pixel or two tall, which a click just beside it must still hit.
  const PickView view = view_from({0.0f, 0.01f, 5.0f});
  const std::vector<PickLoop> loops = {circle(1, {0, 0, 0}, 1.0f, {1, 0, 0}, {0, 0, 1})};
  const glm::vec2 centre = screen(view, {0, 0, 0});
  EXPECT_EQ(pick_hole(loops, view, centre + glm::vec2(20.0f, 4.0f)), 1);
  EXPECT_FALSE(pick_hole(loops, view, centre + glm::vec2(20.0f, 15.0f)));
  // Exactly edge-on the polygon has no area at all.
  const PickView flat = view_from({0.0f, 0.0f, 5.0f});
  EXPECT_EQ(pick_hole(loops, flat, screen(flat, {0, 0, 0}) + glm::vec2(-30.0f, 3.0f)), 1);
}

TEST(Picking, OverlappingLoopsGoToTheOneNearerTheCamera) {
  const PickView view = view_from({0, 0, 5});
  const std::vector<PickLoop> loops = {circle(0, {0, 0, -1}, 1.0f), circle(1, {0, 0, 1}, 1.0f),
                                       circle(2, {0, 0, 0}, 1.0f)};
  EXPECT_EQ(pick_hole(loops, view, screen(view, {0, 0, 0})), 1);
}

TEST(Picking, AClickInsideBeatsANearbyBoundaryOfAnotherLoop) {
  const PickView view = view_from({0, 0, 5});
  const std::vector<PickLoop> loops = {circle(0, {-1.05f, 0, 0}, 1.0f),
                                       circle(1, {1.05f, 0, 0}, 1.0f)};
  // Just inside loop 1, a few pixels from loop 0's rim.
  const glm::vec2 gap = screen(view, {0.0f, 0.0f, 0.0f});
  EXPECT_EQ(pick_hole(loops, view, gap + glm::vec2(4.0f, 0.0f)), 1);
  EXPECT_EQ(pick_hole(loops, view, gap - glm::vec2(4.0f, 0.0f)), 0);
}

TEST(Picking, SegmentDistanceAndContainment) {
  EXPECT_FLOAT_EQ(distance_to_segment({0, 1}, {-1, 0}, {1, 0}), 1.0f);
  EXPECT_FLOAT_EQ(distance_to_segment({3, 0}, {-1, 0}, {1, 0}), 2.0f);
  EXPECT_FLOAT_EQ(distance_to_segment({3, 4}, {0, 0}, {0, 0}), 5.0f);
  const std::vector<glm::vec2> l_shape = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_TRUE(polygon_contains(l_shape, {0.5f, 1.5f}));
  EXPECT_FALSE(polygon_contains(l_shape, {1.5f, 1.5f}));
}

}  // namespace
}  // namespace holefill::viewer
