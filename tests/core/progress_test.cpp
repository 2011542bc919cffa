// fill_holes with a Progress: it reports up to 1 and stops where a cancel leaves a consistent mesh.
#include "holefill/progress.h"

#include <gtest/gtest.h>

#include <cmath>

#include "holefill/fill.h"
#include "holefill/holes.h"
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

}  // namespace
}  // namespace holefill
