#include "interaction.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "scene_arrays.h"

namespace holefill::viewer {
namespace {

const SceneArea kArea{{390.0f, 0.0f}, {890.0f, 800.0f}};

InputEvent mouse(InputEvent::Kind kind, glm::vec2 cursor) {
  InputEvent event;
  event.kind = kind;
  event.cursor = cursor;
  return event;
}

struct Scene {
  Session session;
  Camera camera;
  Interaction interaction;
  Scene() {
    EXPECT_TRUE(session.open(std::filesystem::path(HOLEFILL_TEST_ASSETS) / "bunny.obj"));
    camera.set_viewport(kArea.size);
    fit_mesh(camera, session);
  }
  void send(const InputEvent& event) {
    interaction.handle(event, kArea, false, false, camera, session);
  }
  // Where the hole's boundary centroid appears in the window.
  glm::vec2 on_screen(int hole_id) {
    frame_hole(camera, session, hole_id);
    glm::vec3 centre(0.0f);
    const auto points = boundary_points(session.mesh(), session.holes()[hole_id]);
    for (const auto& p : points) centre += p / static_cast<float>(points.size());
    const PickView view{camera.projection() * camera.view(), kArea.origin, kArea.size};
    return glm::vec2(*project_to_screen(view, centre));
  }
};

TEST(Interaction, AClickOnAFramedHoleSelectsItAndHoverFollowsTheCursor) {
  Scene scene;
  const glm::vec2 hole = scene.on_screen(2);
  scene.send(mouse(InputEvent::Kind::CursorMove, hole));
  EXPECT_EQ(scene.interaction.hovered(), 2);
  scene.send(mouse(InputEvent::Kind::ButtonDown, hole));
  scene.send(mouse(InputEvent::Kind::ButtonUp, hole));
  EXPECT_EQ(scene.session.selected(), 2);
  scene.send(mouse(InputEvent::Kind::CursorMove, kArea.origin + glm::vec2(2.0f, 2.0f)));
  EXPECT_EQ(scene.interaction.hovered(), -1);
}

TEST(Interaction, AShiftClickAddsALoopToTheSelectionAndASecondTakesItOut) {
  Scene scene;
  scene.session.select(2);
  const glm::vec2 hole = scene.on_screen(0);
  InputEvent press = mouse(InputEvent::Kind::ButtonDown, hole);
  press.shift = true;
  InputEvent release = mouse(InputEvent::Kind::ButtonUp, hole);
  release.shift = true;
  scene.send(press);
  scene.send(release);
  EXPECT_EQ(scene.session.selected(), 2);
  EXPECT_EQ(scene.session.joined(), std::vector<int>{0});
  scene.send(press);
  scene.send(release);
  EXPECT_TRUE(scene.session.joined().empty());
  // Shift and a drag pans, and picks nothing.
  const glm::vec3 eye = scene.camera.eye();
  scene.send(press);
  scene.send(mouse(InputEvent::Kind::CursorMove, hole + glm::vec2(40.0f, 0.0f)));
  scene.send(mouse(InputEvent::Kind::ButtonUp, hole + glm::vec2(40.0f, 0.0f)));
  EXPECT_TRUE(scene.session.joined().empty());
  EXPECT_GT(glm::length(scene.camera.eye() - eye), 1e-4f);
}

TEST(Interaction, ADragOrbitsInsteadOfPicking) {
  Scene scene;
  const glm::vec2 hole = scene.on_screen(1);
  const glm::vec3 eye = scene.camera.eye();
  scene.send(mouse(InputEvent::Kind::ButtonDown, hole));
  scene.send(mouse(InputEvent::Kind::CursorMove, hole + glm::vec2(60.0f, 0.0f)));
  scene.send(mouse(InputEvent::Kind::ButtonUp, hole + glm::vec2(60.0f, 0.0f)));
  EXPECT_EQ(scene.session.selected(), -1);
  EXPECT_GT(glm::length(scene.camera.eye() - eye), 1e-3f);
}

TEST(Interaction, ClicksOnThePanelAreLeftToTheUi) {
  Scene scene;
  const glm::vec2 hole = scene.on_screen(0);
  scene.interaction.handle(mouse(InputEvent::Kind::ButtonDown, hole), kArea, true, false,
                           scene.camera, scene.session);
  scene.interaction.handle(mouse(InputEvent::Kind::ButtonUp, hole), kArea, true, false,
                           scene.camera, scene.session);
  EXPECT_EQ(scene.session.selected(), -1);
}

InputEvent key_event(int key, bool control = false, bool shift = false) {
  InputEvent event;
  event.kind = InputEvent::Kind::Key;
  event.key = key;
  event.control = control;
  event.shift = shift;
  return event;
}

// Undo, redo and reset rebuild the mesh, which may take long: the frame loop runs them on the
// worker, so the interaction only hands them over.
TEST(Interaction, UndoRedoAndDeleteAreHandedToTheFrameLoop) {
  Scene scene;
  scene.session.select(2);
  ASSERT_TRUE(scene.session.step(Stage::Triangulated));
  scene.send(key_event('Z', true));
  scene.send(key_event('Y', true));
  scene.send(key_event(kKeyDelete));
  EXPECT_EQ(scene.session.fill(2).stage(), Stage::Triangulated);  // untouched until then
  const auto requests = scene.interaction.take_requests();
  ASSERT_EQ(requests.size(), 3u);
  EXPECT_EQ(requests[0].command, Command::Undo);
  EXPECT_EQ(requests[1].command, Command::Redo);
  EXPECT_EQ(requests[2].command, Command::ResetHole);
}

TEST(Interaction, EscapeDeselects) {
  Scene scene;
  scene.session.select(2);
  scene.send(key_event(kKeyEscape));
  EXPECT_EQ(scene.session.selected(), -1);
}

TEST(Interaction, FileKeysAndDroppedFilesBecomeRequestsForTheFrameLoop) {
  Scene scene;
  scene.send(key_event('S', true));
  scene.send(key_event('S', true, true));
  scene.send(key_event('O', true));
  InputEvent drop;
  drop.kind = InputEvent::Kind::Drop;
  drop.path = "/tmp/dropped.obj";
  scene.send(drop);
  const auto requests = scene.interaction.take_requests();
  ASSERT_EQ(requests.size(), 4u);
  EXPECT_EQ(requests[0].command, Command::Save);
  EXPECT_EQ(requests[1].command, Command::SaveAs);
  EXPECT_EQ(requests[2].command, Command::Open);
  EXPECT_FALSE(requests[3].command);
  EXPECT_EQ(requests[3].path, std::filesystem::path("/tmp/dropped.obj"));
  EXPECT_EQ(scene.session.name(), "bunny.obj");  // nothing opened behind the user's back
  EXPECT_TRUE(scene.interaction.take_requests().empty());
}

TEST(Interaction, KeysGoToTheUiWhenItWantsThem) {
  Scene scene;
  scene.session.select(2);
  scene.interaction.handle(key_event(kKeyEscape), kArea, false, true, scene.camera, scene.session);
  EXPECT_EQ(scene.session.selected(), 2);
}

TEST(Shortcuts, EveryKeyCombinationMeansOneCommand) {
  const auto table = shortcuts();
  for (std::size_t i = 0; i < table.size(); ++i) {
    for (std::size_t j = i + 1; j < table.size(); ++j) {
      EXPECT_FALSE(table[i].key == table[j].key && table[i].control == table[j].control &&
                   table[i].shift == table[j].shift)
          << "shortcuts " << i << " and " << j;
    }
    EXPECT_EQ(command_for_key(table[i].key, table[i].control, table[i].shift), table[i].command);
  }
  EXPECT_FALSE(command_for_key('S', false, false));  // a plain S is not Save
}

// The text size changes while a text field has the keyboard; other shortcuts wait.
TEST(Shortcuts, TextSizeKeysWorkWhateverHasTheKeyboard) {
  Scene scene;
  for (const auto& event : {key_event('+', true), key_event('+', true, true), key_event('-', true),
                            key_event('0', true), key_event('Z', true)}) {
    scene.interaction.handle(event, kArea, false, true, scene.camera, scene.session);
  }
  const auto requests = scene.interaction.take_requests();
  ASSERT_EQ(requests.size(), 4u);
  EXPECT_EQ(requests[0].command, Command::ZoomIn);
  EXPECT_EQ(requests[1].command, Command::ZoomIn);
  EXPECT_EQ(requests[2].command, Command::ZoomOut);
  EXPECT_EQ(requests[3].command, Command::ZoomReset);
}

TEST(Interaction, TheComparisonViewPicksInTheListOnly) {
  Scene scene;
  const glm::vec2 hole = scene.on_screen(2);
  scene.session.select(0);
  scene.session.set_compare(true);
  scene.send(mouse(InputEvent::Kind::CursorMove, hole));
  EXPECT_EQ(scene.interaction.hovered(), -1);
  scene.send(mouse(InputEvent::Kind::ButtonDown, hole));
  scene.send(mouse(InputEvent::Kind::ButtonUp, hole));
  EXPECT_EQ(scene.session.selected(), 0);
  // The camera works in the half under the cursor.
  EXPECT_FLOAT_EQ(scene.camera.viewport().x, 0.5f * kArea.size.x);
}

}  // namespace
}  // namespace holefill::viewer
