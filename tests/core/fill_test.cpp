// The whole pipeline on generated meshes: every filled hole closes, the mesh stays an oriented
// manifold with the expected Euler characteristic, and the original part is untouched.
#include "holefill/fill.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "holefill/holes.h"
#include "holefill/patch.h"
#include "island_meshes.h"
#include "test_meshes.h"

namespace holefill {
namespace {

using testing::euler_characteristic;
using testing::is_oriented_manifold;
using testing::make_grid;
using testing::make_icosphere;
using testing::original_part_unchanged;
using testing::without_faces;

// A sphere with a wavy cap cut out, and a second, small hole elsewhere.
Mesh sphere_with_two_holes() {
  return without_faces(make_icosphere(3), [](const Point& c) {
    const double angle = std::atan2(c[1], c[0]);
    const bool cap = c[2] > 0.55 + 0.12 * std::sin(5.0 * angle);
    const bool small = (c - Point(0.0, 0.0, -1.0)).norm() < 0.25;
    return cap || small;
  });
}

class FillEveryWeight : public ::testing::TestWithParam<WeightKind> {};

TEST_P(FillEveryWeight, ClosesASphereAndKeepsTheOriginalPart) {
  const Mesh before = sphere_with_two_holes();
  const auto holes = find_holes(before);
  ASSERT_EQ(holes.size(), 2u);
  Mesh mesh = before;
  FillOptions options;
  options.triangulate.weight = GetParam();
  const auto fills = fill_holes(mesh, holes, options);
  ASSERT_EQ(fills.size(), 2u);
  for (const auto& fill : fills) {
    EXPECT_FALSE(fill.failed()) << fill.failure;
    EXPECT_EQ(fill.stage(), Stage::Smoothed);
  }
  EXPECT_TRUE(find_holes(mesh).empty());
  EXPECT_TRUE(is_oriented_manifold(mesh));
  EXPECT_EQ(euler_characteristic(mesh), 2);  // a sphere again
  EXPECT_TRUE(original_part_unchanged(before, mesh));
}

TEST_P(FillEveryWeight, FillsOnlyTheInnerHoleOfATerrain) {
  const Mesh before = without_faces(
      make_grid(30, [](double x, double y) { return 0.2 * std::sin(4 * x) * std::cos(3 * y); }),
      [](const Point& c) {
        const double dx = c[0] - 0.5, dy = c[1] - 0.5, angle = std::atan2(dy, dx);
        return std::hypot(dx, dy) < 0.25 + 0.06 * std::sin(7 * angle);
      });
  auto holes = find_holes(before);
  ASSERT_EQ(holes.size(), 2u);  // the outer border and the inner hole
  Mesh mesh = before;
  FillOptions options;
  options.triangulate.weight = GetParam();
  HoleSelection inner;
  inner.hole_ids = {1};  // the border has more edges, so it is hole 0
  const auto fills = fill_holes(mesh, holes, options, inner);
  ASSERT_EQ(fills.size(), 1u);
  EXPECT_FALSE(fills[0].failed());
  EXPECT_EQ(find_holes(mesh).size(), 1u);
  EXPECT_TRUE(is_oriented_manifold(mesh));
  EXPECT_EQ(euler_characteristic(mesh), 1);  // a disk
  EXPECT_TRUE(original_part_unchanged(before, mesh));
}

INSTANTIATE_TEST_SUITE_P(Weights, FillEveryWeight,
                         ::testing::Values(WeightKind::MaxMin, WeightKind::Liepa, WeightKind::Area),
                         [](const auto& info) { return to_string(info.param); });

TEST(Fill, StepsThroughTheStagesInOrder) {
  Mesh mesh = sphere_with_two_holes();
  const auto holes = find_holes(mesh);
  HoleFill fill;
  const FillOptions options;
  ASSERT_TRUE(advance(mesh, holes[0], fill, options));
  EXPECT_EQ(fill.stage(), Stage::Triangulated);
  EXPECT_EQ(fill.stats.new_faces, holes[0].size() - 2);  // a polygon's triangulation
  EXPECT_EQ(fill.stats.new_vertices, 0u);
  ASSERT_TRUE(advance(mesh, holes[0], fill, options));
  EXPECT_EQ(fill.stage(), Stage::Refined);
  EXPECT_GT(fill.stats.new_vertices, 0u);
  // Each new interior vertex adds two faces to a disk's triangulation.
  EXPECT_EQ(fill.stats.new_faces, holes[0].size() - 2 + 2 * fill.stats.new_vertices);
  ASSERT_TRUE(advance(mesh, holes[0], fill, options));
  EXPECT_EQ(fill.stage(), Stage::Smoothed);
  EXPECT_FALSE(advance(mesh, holes[0], fill, options));
  EXPECT_FALSE(fill.failed());
}

TEST(Fill, AllHolesAtOnceGivesTheSameMeshAsOneByOne) {
  const Mesh before = sphere_with_two_holes();
  const auto holes = find_holes(before);
  Mesh together = before, one_by_one = before;
  fill_holes(together, holes, {});
  for (const auto& hole : holes) fill_hole(one_by_one, hole, {});
  ASSERT_EQ(together.n_faces(), one_by_one.n_faces());
  EXPECT_TRUE(original_part_unchanged(one_by_one, together));
}

TEST(Fill, StopsAfterTheRequestedStage) {
  Mesh mesh = sphere_with_two_holes();
  const auto holes = find_holes(mesh);
  FillOptions options;
  options.last_stage = Stage::Triangulated;
  const HoleFill fill = fill_hole(mesh, holes[0], options);
  EXPECT_EQ(fill.stage(), Stage::Triangulated);
  EXPECT_EQ(fill.stats.new_vertices, 0u);
}

TEST(Fill, NeverDuplicatesAnEdgeThatAlreadyJoinsTwoBoundaryVertices) {
  // Two triangles sharing edge A-C: one boundary loop A, B, C, D whose short diagonal A-C
  // already exists. Any weight would like A-C; the only manifold fill uses B-D.
  Mesh before;
  const auto a = before.add_vertex(Point(0.0, 0.0, 0.0));
  const auto b = before.add_vertex(Point(0.5, 2.0, 0.1));
  const auto c = before.add_vertex(Point(1.0, 0.0, 0.0));
  const auto d = before.add_vertex(Point(0.5, -2.0, 0.1));
  before.add_face(a, c, b);
  before.add_face(a, d, c);
  const auto holes = find_holes(before);
  ASSERT_EQ(holes.size(), 1u);
  for (const auto weight : {WeightKind::MaxMin, WeightKind::Liepa, WeightKind::Area}) {
    Mesh mesh = before;
    FillOptions options;
    options.triangulate.weight = weight;
    options.last_stage = Stage::Triangulated;
    const HoleFill fill = fill_hole(mesh, holes[0], options);
    ASSERT_FALSE(fill.failed()) << fill.failure;
    EXPECT_TRUE(is_oriented_manifold(mesh));
    EXPECT_EQ(euler_characteristic(mesh), 2);
    EXPECT_TRUE(mesh.find_halfedge(b, d).is_valid());
    EXPECT_TRUE(find_holes(mesh).empty());
  }
}

TEST(Fill, FillsAPinchedLoopSoThatItsVertexBecomesManifold) {
  // Two triangles touching at one vertex: a single boundary loop through it twice.
  Mesh before;
  VertexHandle v[5];
  const Point points[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  for (int i = 0; i < 5; ++i) v[i] = before.add_vertex(points[i]);
  before.add_face(v[0], v[1], v[2]);
  before.add_face(v[0], v[3], v[4]);
  const auto holes = find_holes(before);
  ASSERT_EQ(holes.size(), 1u);
  EXPECT_TRUE(holes[0].pinched);
  Mesh mesh = before;
  const HoleFill fill = fill_hole(mesh, holes[0], {});
  ASSERT_FALSE(fill.failed()) << fill.failure;
  EXPECT_TRUE(is_oriented_manifold(mesh));  // vertex 0 included: each pass closed one gap
  EXPECT_FALSE(mesh.is_boundary(v[0]));
  EXPECT_TRUE(find_holes(mesh).empty());
}

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
