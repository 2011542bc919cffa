// Filling a hole together with hundreds of small pieces inside it costs time about linear in
// their edges (issue 32, #2): each piece was joined by weighing six candidate bridges, each a
// dynamic program over the polygon joined so far, so 100 pieces in one hole took 58 s in
// `holefill fill` and 400 over 300 s. Sized so that the old way runs past this suite's per-test
// limit.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "holefill/bridge.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/islands.h"
#include "island_meshes.h"
#include "test_meshes.h"

namespace holefill::testing {
namespace {

// The unit sphere (an icosphere) with the cap within 0.9 rad of +z cut away, and `pieces` small
// curved hexagons (six triangles around a raised centre, oriented like the sphere) floating on
// the sphere inside the cut, on a square grid.
Mesh sphere_with_pieces_in_a_hole(int pieces) {
  Mesh mesh = without_isolated_vertices(
      without_faces(make_icosphere(4), [](const Point& c) { return c.normalized()[2] > 0.62; }));
  const double reach = std::sin(0.8);
  const double spacing = 0.95 * std::sqrt(std::numbers::pi * reach * reach / pieces);
  const int steps = static_cast<int>(reach / spacing) + 1;
  int placed = 0;
  for (int i = -steps; i <= steps && placed < pieces; ++i) {
    for (int j = -steps; j <= steps && placed < pieces; ++j) {
      const double x = i * spacing, y = j * spacing, size = 0.3 * spacing;
      if (x * x + y * y > reach * reach) continue;
      auto on_sphere = [](double u, double v) { return Point(u, v, std::sqrt(1 - u * u - v * v)); };
      const VertexHandle centre = mesh.add_vertex(on_sphere(x, y) * (1.0 + 0.4 * size));
      std::vector<VertexHandle> rim;
      for (int k = 0; k < 6; ++k) {
        const double a = 2.0 * std::numbers::pi * k / 6;
        rim.push_back(mesh.add_vertex(on_sphere(x + size * std::cos(a), y + size * std::sin(a))));
      }
      for (int k = 0; k < 6; ++k) mesh.add_face(centre, rim[k], rim[(k + 1) % 6]);
      ++placed;
    }
  }
  return mesh;
}

TEST(JoinCost, AHoleHoldingTwoHundredSmallPiecesClosesIntoASphere) {
  constexpr int kPieces = 200;
  Mesh mesh = sphere_with_pieces_in_a_hole(kPieces);
  const Mesh before = mesh;
  const auto holes = find_holes(mesh);
  ASSERT_EQ(holes.size(), kPieces + 1u);
  ASSERT_EQ(find_islands(mesh, holes).islands[0].size(), static_cast<std::size_t>(kPieces));

  const auto fills = fill_holes(mesh, holes, FillOptions{});
  ASSERT_EQ(fills.size(), 1u);
  EXPECT_FALSE(fills[0].failed()) << fills[0].failure;
  EXPECT_EQ(fills[0].joined_holes.size(), static_cast<std::size_t>(kPieces));
  EXPECT_EQ(fills[0].self_intersections, 0u);
  // One closed surface of genus 0: the hole and every piece's rim closed by one patch.
  EXPECT_TRUE(find_holes(mesh).empty());
  EXPECT_EQ(euler_characteristic(mesh), 2);
  EXPECT_TRUE(is_oriented_manifold(mesh));
  EXPECT_TRUE(original_part_unchanged(before, mesh));
}

TEST(JoinCost, AHoleHoldingMoreLoopsThanOnePatchJoinsIsLeftOpenAtOnce) {
  constexpr int kPieces = static_cast<int>(kMostJoinedLoops);  // one more than the islands allowed
  Mesh mesh = sphere_with_pieces_in_a_hole(kPieces);
  const Mesh before = mesh;
  const auto holes = find_holes(mesh);
  ASSERT_EQ(holes.size(), kPieces + 1u);

  const auto fills = fill_holes(mesh, holes, FillOptions{});
  ASSERT_EQ(fills.size(), 1u);
  EXPECT_TRUE(fills[0].failed());
  EXPECT_EQ(fills[0].failure.kind, FailureKind::TooManyLoops) << fills[0].failure;
  EXPECT_EQ(mesh.n_faces(), before.n_faces());
  EXPECT_EQ(find_holes(mesh).size(), holes.size());
}

}  // namespace
}  // namespace holefill::testing
