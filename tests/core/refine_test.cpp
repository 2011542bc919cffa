// Step 2, refinement: the patch's density follows the surrounding mesh and tau, and the
// relaxation swaps edges by the opposite-angle rule.
#include "holefill/refine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "holefill/fill.h"
#include "holefill/holes.h"
#include "patch_face_set.h"
#include "test_meshes.h"

namespace holefill {
namespace {

using testing::sphere_with_two_holes;

TEST(Refine, PatchEdgesTrackTheSurroundingDensity) {
  const Mesh before = sphere_with_two_holes();
  const auto holes = find_holes(before);
  Mesh mesh = before;
  FillOptions options;
  options.last_stage = Stage::Refined;
  const HoleFill fill = fill_hole(mesh, holes[0], options);
  ASSERT_FALSE(fill.failed());
  double total = 0.0;
  int count = 0;
  for (const auto f : fill.patch.faces) {
    for (const auto e : mesh.fe_range(f)) {
      total += mesh.calc_edge_length(e);
      ++count;
    }
  }
  const double mean_patch_edge = total / count;
  const double surrounding = holes[0].mean_surrounding_edge_length;
  EXPECT_GT(mean_patch_edge, 0.7 * surrounding);
  EXPECT_LT(mean_patch_edge, 1.5 * surrounding);
}

TEST(Refine, LargerTauNeverGivesFewerVertices) {
  const Mesh before = sphere_with_two_holes();
  const auto holes = find_holes(before);
  std::size_t previous = 0;
  for (const double tau : {0.8, 1.0, 1.2, std::sqrt(2.0), 1.7, 2.0}) {
    Mesh mesh = before;
    FillOptions options;
    options.refine.tau = tau;
    options.last_stage = Stage::Refined;
    const HoleFill fill = fill_hole(mesh, holes[0], options);
    EXPECT_GE(fill.stats.new_vertices, previous) << "tau = " << tau;
    previous = fill.stats.new_vertices;
  }
  EXPECT_GT(previous, 0u);
}

// The relaxation's swap test against its definition written with angles: swap when the angles
// opposite the edge sum to more than pi (by a 1e-9 margin) and the swap lowers that sum. Random
// quads folded out of plane, and quads close to co-circular, where a shortcut could misjudge.
TEST(Refine, SwapTestFollowsTheOppositeAngleRule) {
  auto angle_at = [](const Point& corner, const Point& a, const Point& b) {
    const Point u = a - corner, v = b - corner;
    return std::atan2(OpenMesh::cross(u, v).norm(), OpenMesh::dot(u, v));
  };
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int swaps = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    // a, b on the unit circle; c, d near it (exactly on it for some trials), lifted a little.
    const double near = trial % 4 == 0 ? 0.0 : (trial % 4 == 1 ? 1e-9 : 0.3) * unit(rng);
    auto on_circle = [&](double angle, double radius) {
      const double lift = trial % 2 ? 0.2 * unit(rng) : 0.0;
      return Point(radius * std::cos(angle), radius * std::sin(angle), lift);
    };
    const Point a = on_circle(M_PI * (0.5 + 0.4 * unit(rng)), 1.0);
    const Point b = on_circle(-M_PI * (0.5 + 0.4 * unit(rng)), 1.0);
    const Point c = on_circle(M_PI * (0.15 * unit(rng)), 1.0 + near);
    const Point d = on_circle(M_PI * (1.0 + 0.15 * unit(rng)), 1.0 - near);
    Mesh mesh;
    const VertexHandle va = mesh.add_vertex(a), vb = mesh.add_vertex(b), vc = mesh.add_vertex(c),
                       vd = mesh.add_vertex(d);
    mesh.add_face(va, vc, vb);
    mesh.add_face(vb, vd, va);
    EdgeHandle shared;
    for (const auto e : mesh.edges()) {
      if (!mesh.is_boundary(e)) shared = e;
    }
    ASSERT_TRUE(shared.is_valid());
    const double now = angle_at(c, a, b) + angle_at(d, a, b);
    const double swapped = angle_at(a, c, d) + angle_at(b, c, d);
    const bool expected = now > M_PI + 1e-9 && swapped < now - 1e-9;
    EXPECT_EQ(should_swap_edge(mesh, shared), expected) << "trial " << trial;
    swaps += expected;
  }
  EXPECT_GT(swaps, 500);  // both outcomes are exercised
  EXPECT_LT(swaps, 3500);
}

// The refinement's face set against std::set: faces from the patch, newer ones added, and (never
// while refining, but allowed) older ones.
TEST(Refine, PatchFaceSetAnswersLikeASet) {
  std::mt19937 rng(5);
  Patch patch;
  std::set<int> expected;
  for (int i = 0; i < 40; ++i) {
    const int id = 1000 + static_cast<int>(rng() % 200);
    patch.faces.push_back(FaceHandle(id));
    expected.insert(id);
  }
  detail::PatchFaceSet set(patch);
  for (int i = 0; i < 300; ++i) {
    const int id = static_cast<int>(rng() % 1600);
    EXPECT_EQ(set.insert(FaceHandle(id)), expected.insert(id).second) << id;
  }
  for (int id = -1; id < 1700; ++id) {
    EXPECT_EQ(set.contains(FaceHandle(id)), expected.count(id) > 0) << id;
  }
}

}  // namespace
}  // namespace holefill
