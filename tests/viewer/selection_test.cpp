// Islands and bridges in the session: selecting a hole takes its islands along, shift-click
// changes that, one patch closes them all, and Bridge joins two loops. The checks are the core's
// own guarantees (no hole left, one component, a sphere's Euler characteristic) and the core's
// fill_holes on the same mesh as the independent result.
#include <gtest/gtest.h>

#include <cmath>

#include "comparison.h"
#include "hole_table.h"
#include "holefill/stats.h"
#include "island_meshes.h"
#include "scene_arrays.h"
#include "session.h"
#include "test_meshes.h"
#include "test_sessions.h"

namespace holefill::viewer {
namespace {

const Point kNorth(0.0, 0.0, 1.0);

// The unit sphere with an annulus cut around a cap: hole 0 (the outer loop) and its island 1.
Mesh sphere_with_island() {
  return testing::cut_around_islands(testing::make_blob(4, [](const Point&) { return 1.0; }),
                                     {kNorth, 0.7}, {{kNorth, 0.3}});
}

// The sphere stretched to half-axes (1, 1, 2), cut in two around its waist: two facing loops of
// the same size, a gap to bridge (neither is an island of the other).
Mesh capsule_cut_in_two() {
  Mesh mesh = testing::make_icosphere(4);
  for (const auto v : mesh.vertices()) {
    Point p = mesh.point(v);
    p[2] *= 2.0;
    mesh.set_point(v, p);
  }
  return testing::without_isolated_vertices(
      testing::without_faces(mesh, [](const Point& c) { return std::abs(c[2]) < 0.5; }));
}

Session session_of(Mesh mesh) {
  Session session;
  session.load(std::move(mesh), "generated");
  return session;
}

void expect_one_closed_sphere(const Mesh& mesh) {
  EXPECT_TRUE(find_holes(mesh).empty());
  EXPECT_EQ(connected_components(mesh), 1u);
  EXPECT_EQ(testing::euler_characteristic(mesh), 2);
  EXPECT_TRUE(testing::is_oriented_manifold(mesh));
}

TEST(Selection, SelectingAHoleOrItsIslandSelectsBoth) {
  Session session = session_of(sphere_with_island());
  ASSERT_EQ(session.holes().size(), 2u);
  ASSERT_EQ(session.islands().outer[1], 0);
  session.select(1);
  EXPECT_EQ(session.selected(), 0);
  EXPECT_EQ(session.joined(), std::vector<int>{1});
  EXPECT_TRUE(session.in_selection(1));
  EXPECT_EQ(hole_rows(session)[1].stage, "island of 0");
}

TEST(Selection, FillingAHoleClosesItsIslandsWithOnePatchStageByStage) {
  Session session = session_of(sphere_with_island());
  const Mesh loaded = session.mesh();
  session.select(0);
  ASSERT_TRUE(session.step(Stage::Triangulated));
  EXPECT_EQ(session.fill(0).joined_holes, std::vector<int>{1});
  ASSERT_TRUE(session.step(Stage::Refined));
  ASSERT_TRUE(session.step(Stage::Smoothed));
  expect_one_closed_sphere(session.mesh());
  EXPECT_EQ(session.closed_by(1), 0);
  EXPECT_EQ(hole_rows(session)[1].stage, "closed by 0");
  EXPECT_EQ(hole_rows(session)[0].stage, "smoothed +1");
  // The core's fill of the same mesh, all holes with their islands at once, is the same mesh.
  Mesh direct = loaded;
  fill_holes(direct, find_holes(direct), {});
  EXPECT_TRUE(same_mesh(session.mesh(), direct));
  // Clicking the closed island selects the hole whose patch closed it.
  session.select(-1);
  session.select(1);
  EXPECT_EQ(session.selected(), 0);
  ASSERT_TRUE(session.undo());
  ASSERT_TRUE(session.undo());
  ASSERT_TRUE(session.undo());
  EXPECT_TRUE(same_mesh(session.mesh(), loaded));
  EXPECT_EQ(session.closed_by(1), -1);
}

TEST(Selection, ShiftClickTakesAnIslandOutAndTheHoleIsFilledAlone) {
  Session session = session_of(sphere_with_island());
  session.select(0);
  ASSERT_TRUE(session.toggle(1));
  EXPECT_TRUE(session.joined().empty());
  ASSERT_TRUE(session.fill_selected());
  const auto holes = find_holes(session.mesh());
  ASSERT_EQ(holes.size(), 1u);  // the island's loop
  EXPECT_EQ(holes[0].size(), session.holes()[1].size());
  // Its hole is filled without it: the island is a hole of its own now.
  session.select(1);
  EXPECT_EQ(session.selected(), 1);
  EXPECT_FALSE(session.toggle(0));  // filled already
  EXPECT_TRUE(session.notice().error);
}

TEST(Selection, FillAllFillsEachHoleWithItsIslands) {
  Session session = session_of(sphere_with_island());
  ASSERT_TRUE(session.fill_all());
  expect_one_closed_sphere(session.mesh());
  EXPECT_EQ(session.notice().text, "Filled 1 of 1 holes.");
}

TEST(Selection, BridgeJoinsTwoFacingLoopsWithOneBand) {
  Session session = session_of(capsule_cut_in_two());
  ASSERT_EQ(session.holes().size(), 2u);
  ASSERT_EQ(session.islands().outer[1], -1);
  session.select(0);
  EXPECT_FALSE(session.bridge_problem().empty());  // one loop
  ASSERT_TRUE(session.toggle(1));
  EXPECT_EQ(session.bridge_problem(), "");
  ASSERT_TRUE(session.fill_selected());
  expect_one_closed_sphere(session.mesh());
  EXPECT_EQ(session.fill(0).joined_holes, std::vector<int>{1});
  EXPECT_FALSE(session.bridge_problem().empty());  // filled already
  Mesh direct = capsule_cut_in_two();
  HoleSelection bridged;
  bridged.bridges = {{0, 1}};
  fill_holes(direct, find_holes(direct), {}, bridged);
  EXPECT_TRUE(same_mesh(session.mesh(), direct));
}

// Framing a cut through a tube looks from the side, where the gap shows (the normals around the
// cut cancel out), and an island's loop is not taken for the border of an open surface.
TEST(Selection, FramingLooksAcrossATubesCutAndIslandsAreNoBorders) {
  const Mesh capsule = capsule_cut_in_two();
  const auto holes = find_holes(capsule);
  EXPECT_LT(std::abs(hole_view_direction(capsule, holes[0]).z), 0.05f);
  const Session session = session_of(sphere_with_island());
  EXPECT_FALSE(session.is_border(1));
  EXPECT_FALSE(session.is_border(0));
}

TEST(Selection, LoopsTooFarApartAreNotBridged) {
  FillOptions options;
  options.join.max_gap = 0.01;
  Session session = session_of(capsule_cut_in_two());
  session.set_options(options);
  session.select(0);
  ASSERT_TRUE(session.toggle(1));
  EXPECT_NE(session.bridge_problem().find("apart"), std::string::npos) << session.bridge_problem();
}

// The comparison fills the region the selection bounds, islands included, as Fill does: each
// side is the core's fill of the whole mesh with that side's weight.
TEST(Selection, CompareFillsTheHoleWithItsIslands) {
  Session session = session_of(sphere_with_island());
  session.select(0);
  session.set_compare(true);
  const Comparison* comparison = session.comparison();
  ASSERT_NE(comparison, nullptr);
  for (const auto* side : {&comparison->left, &comparison->right}) {
    EXPECT_EQ(side->fill.joined_holes, std::vector<int>{1}) << side->label;
    Mesh direct = sphere_with_island();
    fill_holes(direct, find_holes(direct), side->options);
    EXPECT_TRUE(same_mesh(side->mesh, direct)) << side->label;
    expect_one_closed_sphere(side->mesh);
  }
  // With the island taken out of the selection, it stays open on both sides.
  ASSERT_TRUE(session.toggle(1));
  comparison = session.comparison();
  ASSERT_NE(comparison, nullptr);
  for (const auto* side : {&comparison->left, &comparison->right}) {
    const auto holes = find_holes(side->mesh);
    ASSERT_EQ(holes.size(), 1u) << side->label;
    EXPECT_EQ(holes[0].size(), session.holes()[1].size());
  }
}

// Undo and redo bring back what shift-click had selected: the loops to bridge, or a hole
// without its island.
TEST(Selection, UndoRestoresTheShiftClickedSelection) {
  Session session = session_of(capsule_cut_in_two());
  session.select(0);
  ASSERT_TRUE(session.toggle(1));
  ASSERT_TRUE(session.fill_selected());
  ASSERT_TRUE(session.undo());
  EXPECT_EQ(session.selected(), 0);
  EXPECT_EQ(session.joined(), std::vector<int>{1});
  EXPECT_EQ(session.bridge_problem(), "");
  ASSERT_TRUE(session.redo());
  EXPECT_EQ(session.fill(0).joined_holes, std::vector<int>{1});
  expect_one_closed_sphere(session.mesh());

  Session island = session_of(sphere_with_island());
  island.select(0);
  ASSERT_TRUE(island.toggle(1));  // the island out
  ASSERT_TRUE(island.fill_selected());
  ASSERT_TRUE(island.undo());
  EXPECT_EQ(island.selected(), 0);
  EXPECT_TRUE(island.joined().empty());
  // The selection before it is remembered with each step back: undoing from a hole selected
  // since brings back the one the fill was made on.
  ASSERT_TRUE(island.redo());
  island.select(1);
  ASSERT_TRUE(island.undo());
  EXPECT_EQ(island.selected(), 0);
  EXPECT_TRUE(island.joined().empty());
}

}  // namespace
}  // namespace holefill::viewer
