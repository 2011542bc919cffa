// Fairing (fair.h): the bi-/tri-Laplacian solve continues the surrounding surface where the
// umbrella smoothing flattens it, reproduces planes and quadrics, moves only the patch's own
// vertices, and refuses degenerate input without touching the mesh.
#include "holefill/fair.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <unordered_set>

#include "holefill/fill.h"
#include "holefill/holes.h"
#include "test_meshes.h"

namespace holefill {
namespace {

using testing::make_grid;
using testing::make_icosphere;
using testing::original_part_unchanged;
using testing::without_faces;

// The mesh with its one chosen hole triangulated and refined (not smoothed), and the patch.
struct RefinedHole {
  Mesh mesh;
  Patch patch;
};

RefinedHole refined(const Mesh& cut, int hole_id = 0) {
  RefinedHole result{cut, {}};
  const auto holes = find_holes(cut);
  FillOptions options;
  options.last_stage = Stage::Refined;
  const HoleFill fill = fill_hole(result.mesh, holes.at(hole_id), options);
  EXPECT_FALSE(fill.failed()) << fill.failure;
  result.patch = fill.patch;
  return result;
}

// A unit sphere with a cap of half-angle ~45 degrees cut out: the umbrella smoothing pulls the
// patch toward the flat disk across the cap's rim.
Mesh sphere_without_cap() {
  return without_faces(make_icosphere(3), [](const Point& c) { return c[2] > 0.7; });
}

double mean_sphere_error(const Mesh& mesh, const Patch& patch) {
  double sum = 0.0;
  for (const auto v : patch.new_vertices) sum += std::abs(mesh.point(v).norm() - 1.0);
  return sum / static_cast<double>(patch.new_vertices.size());
}

// A height field over [0,1]^2 (grid spacing 1/29) with a round hole in the middle.
Mesh terrain_with_hole(const std::function<double(double, double)>& height) {
  return without_faces(make_grid(30, height),
                       [](const Point& c) { return std::hypot(c[0] - 0.5, c[1] - 0.5) < 0.3; });
}

// The inner hole of a terrain (the outer border has more edges, so it is hole 0).
constexpr int kInnerHole = 1;

bool same_bits(const Point& a, const Point& b) { return std::memcmp(&a, &b, sizeof(Point)) == 0; }

TEST(Fair, BringsASphereCapMuchCloserToTheSphereThanUmbrellaSmoothing) {
  const RefinedHole start = refined(sphere_without_cap());
  ASSERT_GT(start.patch.new_vertices.size(), 20u);

  Mesh umbrella = start.mesh;
  Patch umbrella_patch = start.patch;
  smooth_patch(umbrella, umbrella_patch);

  Mesh faired = start.mesh;
  const FairResult result = fair_patch(faired, start.patch);
  ASSERT_TRUE(result.solved) << result.problem;

  const double umbrella_error = mean_sphere_error(umbrella, umbrella_patch);
  const double fair_error = mean_sphere_error(faired, start.patch);
  // The dent the issue is about: about 0.14 of the radius. The bi-Laplacian does not reproduce a
  // sphere exactly (over a flat disk its solution is a paraboloid, not a spherical cap; about
  // 0.018 here), but comes far closer.
  EXPECT_GT(umbrella_error, 0.1);
  EXPECT_LT(fair_error, 0.025);
  EXPECT_LT(fair_error, 0.2 * umbrella_error);
}

TEST(Fair, MovesOnlyTheNewVerticesOfThePatch) {
  const RefinedHole start = refined(sphere_without_cap());
  Mesh faired = start.mesh;
  ASSERT_TRUE(fair_patch(faired, start.patch).solved);

  std::unordered_set<int> movable;
  for (const auto v : start.patch.new_vertices) movable.insert(v.idx());
  std::size_t moved = 0;
  for (const auto v : start.mesh.vertices()) {
    const bool same = same_bits(start.mesh.point(v), faired.point(v));
    if (!movable.count(v.idx())) {
      EXPECT_TRUE(same) << "vertex " << v.idx() << " is not the patch's own but moved";
    }
    moved += same ? 0 : 1;
  }
  EXPECT_EQ(moved, movable.size());  // and every patch vertex did move
  EXPECT_EQ(faired.n_faces(), start.mesh.n_faces());
}

TEST(Fair, KeepsAPatchInAFlatSurroundingExactlyInItsPlane) {
  RefinedHole start = refined(terrain_with_hole([](double, double) { return 0.0; }), kInnerHole);
  ASSERT_GT(start.patch.new_vertices.size(), 10u);
  // Lift the patch off the plane, so that staying flat is the solve's doing.
  for (const auto v : start.patch.new_vertices) {
    const Point p = start.mesh.point(v);
    start.mesh.set_point(v, Point(p[0], p[1], 0.1 * std::sin(20.0 * p[0]) + 0.05));
  }
  for (const bool cotangent : {true, false}) {
    for (const int order : {2, 3}) {
      Mesh faired = start.mesh;
      const FairResult result = fair_patch(faired, start.patch, {order, cotangent});
      ASSERT_TRUE(result.solved) << result.problem;
      for (const auto v : start.patch.new_vertices) {
        EXPECT_NEAR(faired.point(v)[2], 0.0, 1e-9) << "order " << order << " cot " << cotangent;
      }
    }
  }
}

TEST(Fair, CotangentWeightsLeaveAFlatPatchWhereItIs) {
  // The cotangent Laplacian of a linear function vanishes on a flat mesh, so the positions a
  // flat patch already has solve the system: fairing must not slide it within its plane.
  const RefinedHole start =
      refined(terrain_with_hole([](double x, double y) { return 0.3 * x - 0.2 * y; }), kInnerHole);
  Mesh faired = start.mesh;
  ASSERT_TRUE(fair_patch(faired, start.patch).solved);
  for (const auto v : start.patch.new_vertices) {
    EXPECT_LT((faired.point(v) - start.mesh.point(v)).norm(), 1e-9);
  }
}

TEST(Fair, ReproducesAShallowParaboloidClosely) {
  // z = a x^2 + b y^2 has a constant Laplacian in the plane, so Delta^2 z = 0 there. On the
  // surface the Laplace-Beltrami operator differs from the planar one by terms of the order of
  // the squared slope, so the bi-Laplacian reproduces the quadric up to that: on this shallow
  // one (slopes up to 0.12, depth 0.018 across the hole) within 2e-4, about 1% of the depth,
  // where the umbrella smoothing misses by 0.014.
  auto height = [](double x, double y) {
    return 0.2 * (x - 0.5) * (x - 0.5) + 0.1 * (y - 0.5) * (y - 0.5);
  };
  const RefinedHole start = refined(terrain_with_hole(height), kInnerHole);
  Mesh faired = start.mesh;
  ASSERT_TRUE(fair_patch(faired, start.patch).solved);
  Mesh umbrella = start.mesh;
  Patch umbrella_patch = start.patch;
  smooth_patch(umbrella, umbrella_patch);

  auto max_error = [&](const Mesh& mesh) {
    double worst = 0.0;
    for (const auto v : start.patch.new_vertices) {
      const Point& p = mesh.point(v);
      worst = std::max(worst, std::abs(p[2] - height(p[0], p[1])));
    }
    return worst;
  };
  EXPECT_LT(max_error(faired), 2e-4);
  EXPECT_GT(max_error(umbrella), 50.0 * max_error(faired));
}

TEST(Fair, TriLaplacianFixesTwoRingsAndAlsoReachesTheSphere) {
  const RefinedHole start = refined(sphere_without_cap());
  Mesh bi = start.mesh, tri = start.mesh;
  const FairResult second = fair_patch(bi, start.patch, {2, true});
  const FairResult third = fair_patch(tri, start.patch, {3, true});
  ASSERT_TRUE(second.solved) << second.problem;
  ASSERT_TRUE(third.solved) << third.problem;
  EXPECT_EQ(second.unknowns, start.patch.new_vertices.size());
  EXPECT_EQ(third.unknowns, start.patch.new_vertices.size());
  // Order 2 holds the boundary and one ring outside it; order 3 one ring more.
  EXPECT_GT(second.fixed_vertices, start.patch.boundary.size());
  EXPECT_GT(third.fixed_vertices, second.fixed_vertices);
  // Continuing the curvature too (C2), it reproduces the cap far better than order 2.
  EXPECT_LT(mean_sphere_error(tri, start.patch), 0.005);
  EXPECT_LT(mean_sphere_error(tri, start.patch), 0.5 * mean_sphere_error(bi, start.patch));
}

TEST(Fair, UniformWeightsAlsoBeatUmbrellaSmoothingOnTheSphere) {
  const RefinedHole start = refined(sphere_without_cap());
  Mesh umbrella = start.mesh, faired = start.mesh;
  Patch umbrella_patch = start.patch;
  smooth_patch(umbrella, umbrella_patch);
  ASSERT_TRUE(fair_patch(faired, start.patch, {2, false}).solved);
  EXPECT_LT(mean_sphere_error(faired, start.patch),
            0.5 * mean_sphere_error(umbrella, umbrella_patch));
}

TEST(Fair, DegeneratePatchIsRefusedAndTheMeshLeftUnchanged) {
  RefinedHole start = refined(sphere_without_cap());
  // Every new vertex on one point: the triangles between them have no area, so the Laplacian
  // has no meaning there.
  for (const auto v : start.patch.new_vertices) start.mesh.set_point(v, Point(0.0, 0.0, 0.7));
  Mesh faired = start.mesh;
  const FairResult result = fair_patch(faired, start.patch);
  EXPECT_FALSE(result.solved);
  EXPECT_NE(result.problem.find("degenerate"), std::string::npos) << result.problem;
  EXPECT_TRUE(original_part_unchanged(start.mesh, faired));
}

TEST(Fair, NonFiniteCoordinatesAreRefusedAndTheMeshLeftUnchanged) {
  RefinedHole start = refined(sphere_without_cap());
  start.mesh.set_point(start.patch.new_vertices[0],
                       Point(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0));
  Mesh faired = start.mesh;
  const FairResult result = fair_patch(faired, start.patch);
  EXPECT_FALSE(result.solved);
  EXPECT_NE(result.problem.find("non-finite"), std::string::npos) << result.problem;
  EXPECT_TRUE(original_part_unchanged(start.mesh, faired));
}

TEST(Fair, PatchWithoutFixedSurroundingIsRefused) {
  // A closed sphere whose every vertex is "new": nothing to continue, the system is singular.
  const Mesh sphere = make_icosphere(1);
  Patch patch;
  for (const auto v : sphere.vertices()) patch.new_vertices.push_back(v);
  for (const auto f : sphere.faces()) patch.faces.push_back(f);
  Mesh faired = sphere;
  const FairResult result = fair_patch(faired, patch);
  EXPECT_FALSE(result.solved);
  EXPECT_FALSE(result.problem.empty());
  EXPECT_TRUE(original_part_unchanged(sphere, faired));
}

TEST(Fair, UnsupportedOrderIsRefused) {
  const RefinedHole start = refined(sphere_without_cap());
  Mesh faired = start.mesh;
  const FairResult result = fair_patch(faired, start.patch, {4, true});
  EXPECT_FALSE(result.solved);
  EXPECT_NE(result.problem.find("order"), std::string::npos) << result.problem;
  EXPECT_TRUE(original_part_unchanged(start.mesh, faired));
}

TEST(Fair, PatchWithoutNewVerticesIsSolvedWithoutChange) {
  const Mesh cut = without_faces(make_icosphere(2), [](const Point& c) { return c[2] > 0.9; });
  Mesh mesh = cut;
  const auto holes = find_holes(cut);
  ASSERT_EQ(holes.size(), 1u);
  FillOptions options;
  options.last_stage = Stage::Triangulated;
  const HoleFill fill = fill_hole(mesh, holes[0], options);
  ASSERT_TRUE(fill.patch.new_vertices.empty());
  const Mesh before = mesh;
  const FairResult result = fair_patch(mesh, fill.patch);
  EXPECT_TRUE(result.solved) << result.problem;
  EXPECT_TRUE(original_part_unchanged(before, mesh));
}

TEST(Fair, PipelineFairsWithoutFallingBackAndKeepsTheOriginalPart) {
  const Mesh cut = sphere_without_cap();
  Mesh mesh = cut;
  FillOptions options;
  options.smooth.method = SmoothMethod::Fair;
  const auto fills = fill_holes(mesh, find_holes(cut), options);
  ASSERT_EQ(fills.size(), 1u);
  EXPECT_EQ(fills[0].stage(), Stage::Smoothed);
  EXPECT_TRUE(fills[0].smoothing_note.empty()) << fills[0].smoothing_note;
  EXPECT_LT(mean_sphere_error(mesh, fills[0].patch), 0.025);
  EXPECT_TRUE(original_part_unchanged(cut, mesh));
  EXPECT_TRUE(find_holes(mesh).empty());
}

}  // namespace
}  // namespace holefill
