// fill_holes with a Progress: it reports up to 1 and stops where a cancel leaves a consistent mesh.
// A cancel carried by FillOptions (triangulate.progress) stops each stage and check at its first
// look: every phase looks, the stage is undone, and the fill says it was cancelled.
#include "holefill/progress.h"

#include <gtest/gtest.h>

#include <cmath>

#include "holefill/fill.h"
#include "holefill/holes.h"
#include "patch_intersections.h"
#include "test_meshes.h"

namespace holefill {
namespace {

// A sphere with three separate holes.
Mesh sphere_with_three_holes() {
  return testing::without_faces(testing::make_icosphere(3), [](const Point& c) {
    return (c - Point(0.0, 0.0, 1.0)).norm() < 0.35 || (c - Point(0.0, 0.0, -1.0)).norm() < 0.3 ||
           (c - Point(1.0, 0.0, 0.0)).norm() < 0.25;
  });
}

TEST(Progress, FillHolesReportsEveryHoleUpToOne) {
  Mesh mesh = sphere_with_three_holes();
  const auto holes = find_holes(mesh);
  ASSERT_EQ(holes.size(), 3u);
  Progress progress;
  EXPECT_EQ(fill_holes(mesh, holes, {}, {}, &progress).size(), 3u);
  EXPECT_DOUBLE_EQ(progress.fraction(), 1.0);
}

TEST(Progress, CancelledBeforeTheStartFillHolesLeavesTheMeshAlone) {
  Mesh mesh = sphere_with_three_holes();
  const Mesh before = mesh;
  const auto holes = find_holes(mesh);
  Progress progress;
  progress.cancel();
  EXPECT_TRUE(fill_holes(mesh, holes, {}, {}, &progress).empty());
  EXPECT_EQ(mesh.n_faces(), before.n_faces());
  EXPECT_EQ(mesh.n_vertices(), before.n_vertices());
  EXPECT_EQ(find_holes(mesh).size(), 3u);
}

TEST(Progress, CancelledAfterTheFirstPatchTheMeshHoldsExactlyTheReturnedFills) {
  Mesh mesh = sphere_with_three_holes();
  const std::size_t faces_before = mesh.n_faces();
  const auto holes = find_holes(mesh);
  // Past one half the patches are being added: cancel once the first one is in.
  Progress progress([&](double fraction) {
    if (fraction > 0.5) progress.cancel();
  });
  const auto fills = fill_holes(mesh, holes, {}, {}, &progress);
  ASSERT_EQ(fills.size(), 1u);
  EXPECT_EQ(mesh.n_faces(), faces_before + fills[0].patch.faces.size());
  EXPECT_EQ(find_holes(mesh).size(), 2u);
}

// A sphere with one hole, its patch stepped (without a cancel) up to `stage`.
struct SteppedHole {
  Mesh mesh = testing::without_faces(testing::make_icosphere(3), [](const Point& c) {
    return (c - Point(0.0, 0.0, 1.0)).norm() < 0.6;
  });
  Hole hole = find_holes(mesh).at(0);
  HoleFill fill;
  explicit SteppedHole(Stage stage) {
    while (fill.stage() < stage) EXPECT_EQ(advance(mesh, hole, fill, {}), StageRun::Ran);
  }
};

std::vector<Point> points_of(const Mesh& mesh) {
  std::vector<Point> points;
  for (const auto v : mesh.vertices()) points.push_back(mesh.point(v));
  return points;
}

// Runs the hole's next stage with a cancelled Progress in the options: the stage fails as
// cancelled and the mesh is exactly as before it.
void expect_cancelled_stage_undone(SteppedHole& hole, FillOptions options) {
  const std::vector<Point> before = points_of(hole.mesh);
  const std::size_t faces = hole.mesh.n_faces();
  const Stage stage = hole.fill.stage();
  Progress progress;
  progress.cancel();
  options.triangulate.progress = &progress;
  EXPECT_EQ(advance(hole.mesh, hole.hole, hole.fill, options), StageRun::Failed);
  EXPECT_EQ(hole.fill.failure, (Failure{FailureKind::Cancelled, kCancelledReason}));
  EXPECT_EQ(hole.fill.stage(), stage);
  EXPECT_EQ(hole.mesh.n_faces(), faces);
  EXPECT_EQ(points_of(hole.mesh), before);
}

TEST(Progress, CancelledTriangulationAddsNoPatch) {
  SteppedHole hole(Stage::Original);
  expect_cancelled_stage_undone(hole, {});
  EXPECT_EQ(find_holes(hole.mesh).size(), 1u);
}

TEST(Progress, CancelledRefinementIsUndone) {
  SteppedHole hole(Stage::Triangulated);
  // Without the cancel this refinement adds vertices: the cancel is what stops it.
  SteppedHole uncancelled(Stage::Refined);
  ASSERT_GT(uncancelled.fill.refinement.splits, 0u);
  expect_cancelled_stage_undone(hole, {});
}

TEST(Progress, CancelledSmoothingIsUndone) {
  SteppedHole hole(Stage::Refined);
  expect_cancelled_stage_undone(hole, {});
}

TEST(Progress, CancelledFairingIsUndoneAndDoesNotFallBackToUmbrella) {
  SteppedHole hole(Stage::Refined);
  FillOptions fair;
  fair.smooth.method = SmoothMethod::Fair;
  expect_cancelled_stage_undone(hole, fair);
  EXPECT_EQ(hole.fill.smoothing_note, "");
  Progress progress;
  progress.cancel();
  const FairResult result = fair_patch(hole.mesh, hole.fill.patch, {}, &progress);
  EXPECT_FALSE(result.solved);
  EXPECT_EQ(result.problem, kCancelledReason);
}

TEST(Progress, CancelledIntersectionCheckStopsBeforeTheFirstPair) {
  // A triangle straight through the sphere's wall intersects it; a cancelled check looks at
  // nothing.
  const Mesh sphere = testing::make_icosphere(2);
  const std::vector<std::array<Point, 3>> through{
      {Point(0.0, 0.0, 0.0), Point(2.0, 0.1, 0.0), Point(2.0, -0.1, 0.05)}};
  ASSERT_FALSE(detail::triangle_intersections(sphere, through, nullptr, nullptr).empty());
  Progress progress;
  progress.cancel();
  EXPECT_TRUE(
      detail::triangle_intersections(sphere, through, nullptr, nullptr, false, &progress).empty());
}

}  // namespace
}  // namespace holefill
