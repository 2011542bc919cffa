// Step 3, umbrella smoothing: it lowers the umbrella energy, matches the operator applied by
// hand, never moves the boundary, and refuses to stand in for fairing.
#include "holefill/smooth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "holefill/fill.h"
#include "holefill/holes.h"
#include "test_meshes.h"

namespace holefill {
namespace {

using testing::original_part_unchanged;
using testing::sphere_with_two_holes;

// The sphere with its first hole filled up to refinement, ready to smooth.
struct RefinedSphere {
  Mesh before, mesh;
  HoleFill fill;
};
RefinedSphere refined_sphere() {
  RefinedSphere sphere{sphere_with_two_holes(), {}, {}};
  sphere.mesh = sphere.before;
  FillOptions options;
  options.last_stage = Stage::Refined;
  sphere.fill = fill_hole(sphere.mesh, find_holes(sphere.before)[0], options);
  return sphere;
}

TEST(Smooth, LowersUmbrellaEnergyAndNeverMovesTheBoundary) {
  auto [before, mesh, fill] = refined_sphere();
  // Disturb the refined patch so there is something to smooth.
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  for (const auto v : fill.patch.new_vertices) {
    mesh.set_point(v, mesh.point(v) + Point(jitter(rng), jitter(rng), jitter(rng)));
  }
  const Mesh refined = mesh;
  const double energy_before = umbrella_energy(mesh, fill.patch);
  smooth_patch(mesh, fill.patch, SmoothOptions{});
  EXPECT_LT(umbrella_energy(mesh, fill.patch), 0.5 * energy_before);
  EXPECT_TRUE(original_part_unchanged(before, mesh));
  for (const auto v : fill.patch.boundary) EXPECT_EQ(mesh.point(v), refined.point(v));
}

// The paper's operator written out on the mesh itself, P <- P + lambda (mean of neighbours - P),
// all vertices at once: the flat-array smoother must give the same positions, bit for bit.
TEST(Smooth, MatchesTheUmbrellaOperatorAppliedOnTheMesh) {
  auto [before, mesh, fill] = refined_sphere();
  ASSERT_GT(fill.patch.new_vertices.size(), 3u);
  Mesh reference = mesh;
  SmoothOptions smooth;
  smooth.iterations = 7;
  smooth.step = 0.3;
  for (int it = 0; it < smooth.iterations; ++it) {
    std::vector<Point> next;
    for (const auto v : fill.patch.new_vertices) {
      Point sum(0, 0, 0);
      int count = 0;
      for (const auto q : reference.vv_range(v)) {
        sum += reference.point(q);
        ++count;
      }
      next.push_back(reference.point(v) + smooth.step * (sum / count - reference.point(v)));
    }
    for (std::size_t i = 0; i < next.size(); ++i) {
      reference.set_point(fill.patch.new_vertices[i], next[i]);
    }
  }
  smooth_patch(mesh, fill.patch, smooth);
  for (const auto v : mesh.vertices()) EXPECT_EQ(mesh.point(v), reference.point(v)) << v.idx();
}

// A vertex listed twice among the patch's new vertices moves once, as the operator says.
TEST(Smooth, AVertexListedTwiceMovesOnce) {
  auto [before, mesh, fill] = refined_sphere();
  ASSERT_GT(fill.patch.new_vertices.size(), 2u);
  Mesh twice = mesh;
  Patch doubled = fill.patch;
  doubled.new_vertices.push_back(doubled.new_vertices[1]);
  smooth_patch(mesh, fill.patch);
  smooth_patch(twice, doubled);
  for (const auto v : mesh.vertices()) EXPECT_EQ(mesh.point(v), twice.point(v)) << v.idx();
}

// smooth_patch is the umbrella operator: asked for fairing it refuses, the mesh untouched, instead
// of smoothing another way than asked; the stage is the pipeline's to advance.
TEST(Smooth, AskedForFairingItRefusesAndLeavesTheStage) {
  auto [before, mesh, fill] = refined_sphere();
  const Mesh untouched = mesh;
  SmoothOptions fairing;
  fairing.method = SmoothMethod::Fair;
  EXPECT_THROW(smooth_patch(mesh, fill.patch, fairing), std::invalid_argument);
  for (const auto v : mesh.vertices()) EXPECT_EQ(mesh.point(v), untouched.point(v)) << v.idx();
  smooth_patch(mesh, fill.patch);
  EXPECT_EQ(fill.patch.stage, Stage::Refined);
}

}  // namespace
}  // namespace holefill
