// Undo, redo, reset and option changes rebuild the mesh from the states kept before the selected
// hole's steps: each is checked against a session that did the same work directly, and the steps
// re-run are counted through the progress the rebuild reports (one report per step run).
#include "replay.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "session.h"
#include "test_sessions.h"

namespace holefill::viewer {
namespace {

// Fills `first` with the default options, then `second` with `options`.
Session filled_in_order(int first, int second, const FillOptions& options = {}) {
  Session session = bunny_session();
  session.select(first);
  EXPECT_TRUE(session.fill_selected());
  session.select(second);
  session.set_options(options);
  EXPECT_TRUE(session.fill_selected());
  return session;
}

// Applies `change` and returns how many steps it ran again.
int apply_counting_steps(Session& session, const std::optional<LogChange>& change) {
  EXPECT_TRUE(change);
  if (!change) return -1;
  int steps = 0;
  Progress progress([&steps](double) { ++steps; });
  auto result = session.compute(*change, &progress);
  EXPECT_TRUE(result);
  if (result) session.apply(std::move(*result));
  return steps;
}

FillOptions with_tau(double tau) {
  FillOptions options;
  options.refine.tau = tau;
  return options;
}

TEST(Replay, ChangingTauRerunsRefinementAndSmoothingOnly) {
  Session session = filled_in_order(2, 0);
  EXPECT_EQ(apply_counting_steps(session, session.options_request(with_tau(1.2))), 2);
  EXPECT_TRUE(same_mesh(session.mesh(), filled_in_order(2, 0, with_tau(1.2)).mesh()));
  EXPECT_EQ(session.fill(0).stage(), Stage::Smoothed);
  EXPECT_DOUBLE_EQ(session.options().refine.tau, 1.2);
  // Back to the first value, and forth again: from the kept triangulation each time.
  EXPECT_EQ(apply_counting_steps(session, session.undo_request()), 2);
  EXPECT_TRUE(same_mesh(session.mesh(), filled_in_order(2, 0).mesh()));
  EXPECT_EQ(apply_counting_steps(session, session.redo_request()), 2);
  EXPECT_TRUE(same_mesh(session.mesh(), filled_in_order(2, 0, with_tau(1.2)).mesh()));
}

TEST(Replay, ChangingSmoothingRerunsTheSmoothingOnly) {
  Session session = filled_in_order(2, 0);
  FillOptions options;
  options.smooth.iterations = 3;
  EXPECT_EQ(apply_counting_steps(session, session.options_request(options)), 1);
  EXPECT_TRUE(same_mesh(session.mesh(), filled_in_order(2, 0, options).mesh()));
}

TEST(Replay, ChangingTheWeightRerunsTheSelectedHoleOnly) {
  Session session = filled_in_order(2, 0);
  FillOptions options;
  options.triangulate.weight = WeightKind::Liepa;
  EXPECT_EQ(apply_counting_steps(session, session.options_request(options)), 3);
  EXPECT_TRUE(same_mesh(session.mesh(), filled_in_order(2, 0, options).mesh()));
}

TEST(Replay, UndoingAndResettingTheLastFilledHoleRunsNothing) {
  Session session = filled_in_order(2, 0);
  Session only_two = bunny_session();
  only_two.select(2);
  ASSERT_TRUE(only_two.fill_selected());
  EXPECT_EQ(apply_counting_steps(session, session.undo_request()), 0);
  EXPECT_TRUE(same_mesh(session.mesh(), only_two.mesh()));
  EXPECT_EQ(session.fill(0).stage(), Stage::Original);
  ASSERT_TRUE(session.redo());
  session.select(0);
  EXPECT_EQ(apply_counting_steps(session, session.reset_request()), 0);
  EXPECT_TRUE(same_mesh(session.mesh(), only_two.mesh()));
}

// A hole filled before another: its new options cannot start from a kept state, so the whole
// log replays, in its order, as it did before these checkpoints existed.
TEST(Replay, AHoleFilledBeforeAnotherReplaysEverything) {
  Session session = filled_in_order(0, 2);
  session.select(0);
  EXPECT_EQ(apply_counting_steps(session, session.options_request(with_tau(1.2))), 6);
  Session direct = bunny_session();
  direct.select(0);
  direct.set_options(with_tau(1.2));
  ASSERT_TRUE(direct.fill_selected());
  direct.select(2);
  direct.set_options({});
  ASSERT_TRUE(direct.fill_selected());
  EXPECT_TRUE(same_mesh(session.mesh(), direct.mesh()));
}

TEST(Replay, OptionsWithoutAFilledHoleSelectedChangeNoMesh) {
  Session session = filled_in_order(2, 0);
  session.select(1);
  EXPECT_FALSE(session.options_request(with_tau(1.2)));
  session.select(0);
  EXPECT_FALSE(session.options_request(session.options()));  // the same options
}

TEST(Replay, TheTriangulationSeesTheProgressAndStopsWhenCancelled) {
  Session session = bunny_session();
  MeshState state{session.mesh(), std::vector<HoleFill>(session.holes().size())};
  Progress cancelled;
  cancelled.cancel();
  EXPECT_FALSE(run_step(state, session.holes(), make_step(0, {}, {}), nullptr, &cancelled));
  EXPECT_EQ(state.mesh.n_faces(), session.mesh().n_faces());
  // The progress is not kept in the log.
  session.select(0);
  ASSERT_TRUE(session.step(Stage::Triangulated));
  EXPECT_EQ(session.log().back().options.triangulate.progress, nullptr);
}

// Keeping a side of the comparison makes the hole's fill that side's: the same mesh.
TEST(Replay, KeepingTheLeftSideOfTheComparisonFillsTheHoleAsItShows) {
  Session session = filled_in_order(2, 0);
  EXPECT_FALSE(session.keep_request(false));  // no comparison showing
  session.set_compare(true);
  const Comparison* comparison = session.comparison();
  ASSERT_TRUE(comparison);
  const Mesh left = comparison->left.mesh;
  EXPECT_EQ(apply_counting_steps(session, session.keep_request(false)), 3);
  EXPECT_TRUE(same_mesh(session.mesh(), left));
  EXPECT_EQ(session.options().triangulate.weight, WeightKind::Liepa);
  EXPECT_FALSE(session.compare());
  ASSERT_TRUE(session.undo());
  EXPECT_TRUE(same_mesh(session.mesh(), filled_in_order(2, 0).mesh()));
}

TEST(Replay, OnlyTheStageAnOptionAffectsCounts) {
  FillOptions a, b;
  b.refine.tau = 1.1;
  EXPECT_TRUE(same_for_stage(Stage::Triangulated, a, b));
  EXPECT_FALSE(same_for_stage(Stage::Refined, a, b));
  EXPECT_TRUE(same_for_stage(Stage::Smoothed, a, b));
  b = a;
  b.triangulate.weight = WeightKind::Area;
  EXPECT_FALSE(same_for_stage(Stage::Triangulated, a, b));
  EXPECT_TRUE(same_for_stage(Stage::Refined, a, b));
}

// A replay from the loaded mesh keeps that mesh as the state before the hole's first step,
// shared rather than copied (a million-face mesh is about 100 MB); the later states are its own.
TEST(Replay, TheLoadedMeshIsKeptSharedNotCopied) {
  const Session session = bunny_session();
  const auto loaded = std::make_shared<const MeshState>(
      MeshState{session.mesh(), std::vector<HoleFill>(session.holes().size())});
  std::vector<FillStep> log;
  for (int stage = 0; stage < 3; ++stage) log.push_back(make_step(0, {}, {}));
  const auto rebuilt = rebuild(loaded, session.holes(), log, 0, {}, nullptr);
  ASSERT_TRUE(rebuilt);
  ASSERT_EQ(rebuilt->checkpoints.states.size(), 3u);
  EXPECT_EQ(rebuilt->checkpoints.states[0], loaded);
  EXPECT_NE(rebuilt->checkpoints.states[1], loaded);
  EXPECT_TRUE(same_mesh(loaded->mesh, session.mesh()));  // untouched
  Session direct = bunny_session();
  direct.select(0);
  ASSERT_TRUE(direct.fill_selected());
  EXPECT_TRUE(same_mesh(rebuilt->state.mesh, direct.mesh()));
  // After another hole's step, the state before hole 0's steps is that step's result.
  log.insert(log.begin(), make_step(1, {}, {}));
  const auto after_other = rebuild(loaded, session.holes(), log, 0, {}, nullptr);
  ASSERT_TRUE(after_other);
  ASSERT_FALSE(after_other->checkpoints.states.empty());
  EXPECT_NE(after_other->checkpoints.states[0], loaded);
  EXPECT_GT(after_other->checkpoints.states[0]->mesh.n_faces(), loaded->mesh.n_faces());
}

}  // namespace
}  // namespace holefill::viewer
