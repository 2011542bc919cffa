// The whole pipeline on generated meshes: every filled hole closes, the mesh stays an oriented
// manifold with the expected Euler characteristic, and the original part is untouched.
#include "holefill/fill.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "holefill/errors.h"
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
using testing::sphere_with_two_holes;
using testing::without_faces;

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
  ASSERT_EQ(advance(mesh, holes[0], fill, options), StageRun::Ran);
  EXPECT_EQ(fill.stage(), Stage::Triangulated);
  EXPECT_EQ(fill.stats.new_faces, holes[0].size() - 2);  // a polygon's triangulation
  EXPECT_EQ(fill.stats.new_vertices, 0u);
  ASSERT_EQ(advance(mesh, holes[0], fill, options), StageRun::Ran);
  EXPECT_EQ(fill.stage(), Stage::Refined);
  EXPECT_GT(fill.stats.new_vertices, 0u);
  // Each new interior vertex adds two faces to a disk's triangulation.
  EXPECT_EQ(fill.stats.new_faces, holes[0].size() - 2 + 2 * fill.stats.new_vertices);
  ASSERT_EQ(advance(mesh, holes[0], fill, options), StageRun::Ran);
  EXPECT_EQ(fill.stage(), Stage::Smoothed);
  const std::size_t faces = mesh.n_faces();
  EXPECT_EQ(advance(mesh, holes[0], fill, options), StageRun::AllDone);
  EXPECT_EQ(mesh.n_faces(), faces);
  EXPECT_FALSE(fill.failed());
}

TEST(Fill, AStageThatCannotRunSaysFailedEveryTimeAndLeavesTheMesh) {
  // A band whose inner rim runs out and back along one line through four points: every
  // triangle across that hole has zero area, so its triangulation is refused.
  Mesh mesh;
  std::vector<VertexHandle> v;
  for (const Point& p : {Point(0, 0, 0), Point(1, 0, 0), Point(2, 0, 0), Point(3, 0, 0),
                         Point(0, -1, 1), Point(1, -1, 1), Point(3, 1, 1), Point(0, 1, 1)}) {
    v.push_back(mesh.add_vertex(p));
  }
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    mesh.add_face(v[i], v[4 + i], v[4 + j]);
    mesh.add_face(v[i], v[4 + j], v[j]);
  }
  const auto holes = find_holes(mesh);
  const auto rim = std::find_if(holes.begin(), holes.end(),
                                [](const Hole& h) { return h.vertices[0].idx() < 4; });
  ASSERT_NE(rim, holes.end());
  const Mesh before = mesh;
  HoleFill fill;
  EXPECT_EQ(advance(mesh, *rim, fill, FillOptions{}), StageRun::Failed);
  EXPECT_TRUE(fill.failed());
  EXPECT_EQ(fill.stage(), Stage::Original);
  EXPECT_EQ(advance(mesh, *rim, fill, FillOptions{}), StageRun::Failed);
  EXPECT_EQ(mesh.n_faces(), before.n_faces());
  EXPECT_TRUE(original_part_unchanged(before, mesh));
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
  // Two faces of a triangular bipyramid touching at one equator vertex (v[0]): a single boundary
  // loop through it twice.
  Mesh before;
  VertexHandle v[5];
  const Point points[] = {{-0.5, 0.866, 0}, {1, 0, 0}, {0, 0, 1}, {-0.5, -0.866, 0}, {0, 0, -1}};
  for (int i = 0; i < 5; ++i) v[i] = before.add_vertex(points[i]);
  before.add_face(v[1], v[0], v[2]);
  before.add_face(v[3], v[0], v[4]);
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

TEST(Fill, AStaleHoleOrOneNotOnTheBoundaryIsRefusedBeforeAnyWork) {
  Mesh mesh = testing::sphere_with_two_holes();
  const auto holes = find_holes(mesh);
  ASSERT_EQ(holes.size(), 2u);
  EXPECT_TRUE(is_boundary_loop(mesh, holes[1]));
  ASSERT_FALSE(fill_hole(mesh, holes[1], {}).failed());
  EXPECT_FALSE(is_boundary_loop(mesh, holes[1]));
  const std::size_t faces = mesh.n_faces();
  // The same Hole again: filled since it was found.
  EXPECT_THROW(fill_hole(mesh, holes[1], {}), InvalidHoleError);
  HoleFill fill;
  EXPECT_THROW(advance(mesh, holes[1], fill, {}), InvalidHoleError);
  EXPECT_THROW(fill_holes(mesh, holes, {}), InvalidHoleError);
  EXPECT_EQ(mesh.n_faces(), faces);
  // A loop made by hand around a face: its halfedges are not on the boundary.
  Hole inside;
  for (const auto h : mesh.fh_range(*mesh.faces_begin())) {
    inside.halfedges.push_back(h);
    inside.vertices.push_back(mesh.from_vertex_handle(h));
  }
  EXPECT_FALSE(is_boundary_loop(mesh, inside));
  EXPECT_THROW(fill_hole(mesh, inside, {}), InvalidHoleError);
  // The other hole, found before the fill, is still one: it fills.
  EXPECT_TRUE(is_boundary_loop(mesh, holes[0]));
  EXPECT_FALSE(fill_hole(mesh, holes[0], {}).failed());
}

}  // namespace
}  // namespace holefill
