// Holes with islands (islands.h, bridge.h): annuli cut around pieces left floating on spheres and
// blobs close into one surface of the right genus, as close to the cut-away surface as an ordinary
// hole's patch, and the ambiguous cases are refused with the mesh left as it was.
#include "holefill/islands.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/stats.h"
#include "island_meshes.h"
#include "test_meshes.h"

namespace holefill {
namespace {

using testing::Cap;
using testing::cut_around_islands;
using testing::euler_characteristic;
using testing::is_oriented_manifold;
using testing::make_blob;
using testing::original_part_unchanged;
using testing::without_faces;
using testing::without_isolated_vertices;

const Point kNorth(0.0, 0.0, 1.0);

double unit_radius(const Point&) { return 1.0; }

double blob_radius(const Point& d) {
  return 1.0 + 0.15 * std::sin(3.0 * d[0]) * std::sin(2.0 * d[1] + 1.0) +
         0.1 * std::cos(2.0 * d[2]);
}

// A direction `angle` away from the north pole, at `azimuth` around it.
Point tilted(double angle, double azimuth) {
  return Point(std::sin(angle) * std::cos(azimuth), std::sin(angle) * std::sin(azimuth),
               std::cos(angle));
}

// Mean distance of the patch's new vertices from the blob's surface, measured along the radius.
double mean_distance_to(const Mesh& mesh, const HoleFill& fill,
                        const testing::RadiusFunction& radius) {
  double sum = 0.0;
  for (const auto v : fill.patch.new_vertices) {
    const Point& p = mesh.point(v);
    sum += std::abs(p.norm() - radius(p.normalized()));
  }
  return fill.patch.new_vertices.empty() ? 0.0 : sum / fill.patch.new_vertices.size();
}

// Fills every hole of `before` with its islands and checks what every island fill must give: one
// closed, oriented, manifold surface of the sphere's genus, with the original part untouched.
std::vector<HoleFill> fill_and_check_closed(const Mesh& before, Mesh& after, std::size_t islands,
                                            const FillOptions& options = {}) {
  const auto holes = find_holes(before);
  EXPECT_EQ(holes.size(), islands + 1);
  after = before;
  const auto fills = fill_holes(after, holes, options);
  EXPECT_EQ(fills.size(), 1u);
  for (const auto& fill : fills) {
    EXPECT_FALSE(fill.failed()) << fill.failure;
    EXPECT_EQ(fill.joined_holes.size(), islands);
    EXPECT_EQ(fill.self_intersections, 0u);
    EXPECT_EQ(count_patch_intersections(after, fill.patch), 0u);
  }
  EXPECT_TRUE(find_holes(after).empty());
  EXPECT_EQ(connected_components(after), 1u);
  EXPECT_EQ(euler_characteristic(after), 2);
  EXPECT_TRUE(is_oriented_manifold(after));
  EXPECT_TRUE(original_part_unchanged(before, after));
  return fills;
}

TEST(Islands, FindsTheCapLeftInsideAnAnnulusCut) {
  const Mesh mesh = cut_around_islands(make_blob(4, unit_radius), {kNorth, 0.7}, {{kNorth, 0.3}});
  ASSERT_EQ(connected_components(mesh), 2u);
  const auto holes = find_holes(mesh);
  ASSERT_EQ(holes.size(), 2u);
  const IslandMap map = find_islands(mesh, holes);
  EXPECT_EQ(map.islands[0], std::vector<int>{1});  // the larger loop is the outer one
  EXPECT_EQ(map.outer[1], 0);
  EXPECT_TRUE(map.islands[1].empty());
  EXPECT_TRUE(map.note[0].empty() && map.note[1].empty());
  IslandOptions off;
  off.detect = false;
  EXPECT_TRUE(find_islands(mesh, holes, off).islands[0].empty());
}

// Copies of one mesh side by side, `spacing` apart along x, y and z in turn.
Mesh copies_apart(const Mesh& part, int count, double spacing) {
  Mesh mesh;
  for (int c = 0; c < count; ++c) {
    testing::append_mesh(mesh, part,
                         Point(spacing * (c % 3), spacing * (c / 3 % 3), spacing * (c / 9)));
  }
  return mesh;
}

// Holes are compared only with the loops near them (a k-d tree of centroids): each of many
// spheres, close enough that a hole's search reaches its neighbours' loops, keeps its own island
// and no other, exactly as with one sphere.
TEST(Islands, EachOfManyHolesFindsItsOwnIslandAmongItsNeighbours) {
  const Mesh one = cut_around_islands(make_blob(3, unit_radius), {kNorth, 0.7}, {{kNorth, 0.3}});
  constexpr int kCopies = 20;
  const Mesh mesh = copies_apart(one, kCopies, 2.2);
  const auto holes = find_holes(mesh);
  ASSERT_EQ(holes.size(), 2u * kCopies);
  const IslandMap map = find_islands(mesh, holes);
  const std::vector<int> component = component_labels(mesh);
  int outer_holes = 0;
  for (const auto& hole : holes) {
    const int id = hole.id;
    EXPECT_TRUE(map.note[id].empty()) << map.note[id];
    if (map.islands[id].empty()) {
      // An island: inside exactly one hole, of the same sphere (the copy's outer surface).
      ASSERT_GE(map.outer[id], 0) << id;
      const Hole& outer = holes[map.outer[id]];
      EXPECT_LT((outer.centroid - hole.centroid).norm(), 0.5) << id;
      EXPECT_NE(component[outer.vertices[0].idx()], component[hole.vertices[0].idx()]);
      continue;
    }
    ++outer_holes;
    ASSERT_EQ(map.islands[id].size(), 1u) << id;
    EXPECT_EQ(map.outer[map.islands[id][0]], id);
    EXPECT_EQ(map.outer[id], -1);
  }
  EXPECT_EQ(outer_holes, kCopies);
}

TEST(Islands, SeparateHolesOfOneSurfaceAreNoIslands) {
  // Two holes of one sphere, the small one near the large one's plane: same component.
  const Mesh mesh =
      without_isolated_vertices(without_faces(make_blob(3, unit_radius), [](const Point& c) {
        return Cap{kNorth, 0.8}.contains(c) || Cap{tilted(1.6, 0.0), 0.3}.contains(c);
      }));
  const auto holes = find_holes(mesh);
  ASSERT_EQ(holes.size(), 2u);
  const IslandMap map = find_islands(mesh, holes);
  EXPECT_TRUE(map.islands[0].empty() && map.islands[1].empty());
}

TEST(Islands, FillsAnAnnulusAroundOneIslandOnASphereAsCloseAsAnOrdinaryHole) {
  const Mesh before = cut_around_islands(make_blob(4, unit_radius), {kNorth, 0.7}, {{kNorth, 0.3}});
  Mesh after;
  const auto fills = fill_and_check_closed(before, after, 1);
  ASSERT_FALSE(fills.empty());
  // The same hole without its island: the island's patch covers less, and bends no more.
  const Mesh plain_before = cut_around_islands(make_blob(4, unit_radius), {kNorth, 0.7}, {});
  Mesh plain = plain_before;
  const auto plain_fills = fill_holes(plain, find_holes(plain_before), {});
  ASSERT_EQ(plain_fills.size(), 1u);
  const double island_distance = mean_distance_to(after, fills[0], unit_radius);
  const double plain_distance = mean_distance_to(plain, plain_fills[0], unit_radius);
  EXPECT_GT(plain_distance, 0.0);
  EXPECT_LT(island_distance, 1.2 * plain_distance);
}

TEST(Islands, FillsAroundThreeIslandsOnASphere) {
  const Mesh before = cut_around_islands(
      make_blob(4, unit_radius), {kNorth, 0.85},
      {{tilted(0.45, 0.0), 0.17}, {tilted(0.45, 2.1), 0.17}, {tilted(0.45, 4.2), 0.17}});
  ASSERT_EQ(connected_components(before), 4u);
  Mesh after;
  fill_and_check_closed(before, after, 3);
}

// The islands found beforehand (as preparing a mesh finds them) and handed to fill_holes give the
// fill that finding them inside gives, vertex for vertex and face for face.
TEST(Islands, IslandsFoundBeforehandGiveTheSameFill) {
  const Mesh before = cut_around_islands(
      make_blob(4, unit_radius), {kNorth, 0.85},
      {{tilted(0.45, 0.0), 0.17}, {tilted(0.45, 2.1), 0.17}, {tilted(0.45, 4.2), 0.17}});
  const auto holes = find_holes(before);
  const FillOptions options;
  const IslandMap islands = find_islands(before, holes, options.islands);
  ASSERT_EQ(std::count(islands.outer.begin(), islands.outer.end(), -1), 1);  // three islands
  Mesh found_inside = before, found_before = before;
  const auto inside = fill_holes(found_inside, holes, options);
  const auto handed = fill_holes(found_before, holes, islands, options);
  ASSERT_EQ(handed.size(), 1u);
  EXPECT_EQ(handed[0].joined_holes, inside[0].joined_holes);
  ASSERT_EQ(found_before.n_vertices(), found_inside.n_vertices());
  ASSERT_EQ(found_before.n_faces(), found_inside.n_faces());
  for (const auto v : found_inside.vertices()) {
    EXPECT_EQ(found_before.point(v), found_inside.point(v));
  }
  for (const auto f : found_inside.faces()) {
    auto a = found_inside.cfv_iter(f), b = found_before.cfv_iter(f);
    for (int corner = 0; corner < 3; ++corner, ++a, ++b) EXPECT_EQ(*a, *b);
  }
}

TEST(Islands, FillsAroundTwoIslandsOnABlobAsCloseAsAnOrdinaryHole) {
  const Point axis = Point(1.0, 0.6, 0.4).normalized();
  const Point side = OpenMesh::cross(axis, kNorth).normalized();
  const Cap cut{axis, 0.8};
  const Mesh before = cut_around_islands(
      make_blob(4, blob_radius), cut,
      {{(axis + 0.35 * side).normalized(), 0.2}, {(axis - 0.35 * side).normalized(), 0.2}});
  Mesh after;
  const auto fills = fill_and_check_closed(before, after, 2);
  ASSERT_FALSE(fills.empty());
  const Mesh plain_before = cut_around_islands(make_blob(4, blob_radius), cut, {});
  Mesh plain = plain_before;
  const auto plain_fills = fill_holes(plain, find_holes(plain_before), {});
  ASSERT_EQ(plain_fills.size(), 1u);
  EXPECT_LT(mean_distance_to(after, fills[0], blob_radius),
            1.2 * mean_distance_to(plain, plain_fills[0], blob_radius));
}

TEST(Islands, EveryLoopOnItsOwnWhenDetectionIsOff) {
  const Mesh before = cut_around_islands(make_blob(4, unit_radius), {kNorth, 0.7}, {{kNorth, 0.3}});
  Mesh after = before;
  FillOptions options;
  options.islands.detect = false;
  const auto fills = fill_holes(after, find_holes(before), options);
  ASSERT_EQ(fills.size(), 2u);
  EXPECT_TRUE(fills[0].joined_holes.empty());
  EXPECT_TRUE(find_holes(after).empty());
  EXPECT_EQ(connected_components(after), 2u);  // two closed pieces, one inside the other
}

// Joined along a tree of shortest bridges, as holes with many islands are (JoinOptions::
// weighed_loops; tests/cost/join_cost_test.cpp has 200 pieces), the same holes close as well.
TEST(Islands, FillsAroundThreeIslandsJoinedAlongATreeOfShortestBridges) {
  const Mesh before = cut_around_islands(
      make_blob(4, unit_radius), {kNorth, 0.85},
      {{tilted(0.45, 0.0), 0.17}, {tilted(0.45, 2.1), 0.17}, {tilted(0.45, 4.2), 0.17}});
  FillOptions options;
  options.join.weighed_loops = 0;
  Mesh after;
  fill_and_check_closed(before, after, 3, options);
}

// Generated blobs with islands of random number, size and place, never seen by the code: each
// closes into one surface of a sphere's genus, whether bridges are weighed or follow a tree.
TEST(Islands, RandomBlobsWithIslandsCloseIntoOneSphere) {
  std::mt19937 rng(20260101);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 6; ++trial) {
    const double a = 0.1 + 0.1 * unit(rng), b = 3.0 * unit(rng), c = 2.0 + 2.0 * unit(rng);
    auto radius = [=](const Point& d) {
      return 1.0 + a * std::sin(c * d[0] + b) * std::cos(c * d[1]);
    };
    const Point axis = tilted(std::numbers::pi * unit(rng), 2.0 * std::numbers::pi * unit(rng));
    const Point side = OpenMesh::cross(axis, Point(0.3, 0.5, 0.8)).normalized();
    const Point other_side = OpenMesh::cross(axis, side);
    const int islands = 1 + trial % 3;
    std::vector<Cap> caps;
    for (int i = 0; i < islands; ++i) {
      const double azimuth = 2.0 * std::numbers::pi * (i + 0.2 * unit(rng)) / islands;
      const double offset = islands == 1 ? 0.2 * unit(rng) : 0.42;
      caps.push_back({(axis + offset * (std::cos(azimuth) * side + std::sin(azimuth) * other_side))
                          .normalized(),
                      0.15 + 0.04 * unit(rng)});
    }
    const Mesh before = cut_around_islands(make_blob(4, radius), {axis, 0.85}, caps);
    SCOPED_TRACE("trial " + std::to_string(trial));
    Mesh after;
    fill_and_check_closed(before, after, islands);
    FillOptions along_tree;
    along_tree.join.weighed_loops = 0;
    fill_and_check_closed(before, after, islands, along_tree);
  }
}

}  // namespace
}  // namespace holefill
