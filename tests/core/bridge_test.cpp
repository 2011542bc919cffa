// Gaps between surfaces (bridge.h, HoleSelection::bridges): a capsule or tube cut in two and two
// facing sheets are joined by one band of the right genus; holes too far apart are refused with the
// mesh left as it was; islands touching their hole and islands of two holes are left out of it.
#include "holefill/bridge.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "exact_intersections.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/stats.h"
#include "island_meshes.h"
#include "test_meshes.h"

namespace holefill {
namespace {

using testing::euler_characteristic;
using testing::is_oriented_manifold;
using testing::make_icosphere;
using testing::original_part_unchanged;
using testing::without_faces;
using testing::without_isolated_vertices;

// The unit sphere stretched to half-axes (1, 1, 2), without the faces whose centroid `cut` takes.
Mesh capsule_without(const std::function<bool(const Point&)>& cut) {
  Mesh mesh = make_icosphere(4);
  for (const auto v : mesh.vertices()) {
    Point p = mesh.point(v);
    p[2] *= 2.0;
    mesh.set_point(v, p);
  }
  return without_isolated_vertices(without_faces(mesh, cut));
}

// The largest |sqrt(x^2 + y^2 + (z/2)^2) - 1| over the patch's new vertices: about their distance
// from the capsule's surface.
double farthest_from_capsule(const Mesh& mesh, const HoleFill& fill) {
  double worst = 0.0;
  for (const auto v : fill.patch.new_vertices) {
    const Point& p = mesh.point(v);
    worst = std::max(worst, std::abs(std::hypot(p[0], p[1], p[2] / 2.0) - 1.0));
  }
  return worst;
}

// Appends a flat sheet of square cells of side h over [x0, x1] x [y0, y1] at height z, facing up
// (+z) or down, without the cells whose centre `removed` names.
void add_sheet(Mesh& mesh, Point low, Point high, double h, bool up,
               const std::function<bool(double, double)>& removed) {
  const int nx = static_cast<int>(std::lround((high[0] - low[0]) / h));
  const int ny = static_cast<int>(std::lround((high[1] - low[1]) / h));
  std::vector<VertexHandle> at;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) at.push_back(mesh.add_vertex(low + Point(i * h, j * h, 0.0)));
  }
  auto corner = [&](int i, int j) { return at[j * (nx + 1) + i]; };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      if (removed && removed(low[0] + (i + 0.5) * h, low[1] + (j + 0.5) * h)) continue;
      VertexHandle a = corner(i, j), b = corner(i + 1, j), c = corner(i + 1, j + 1),
                   d = corner(i, j + 1);
      if (!up) std::swap(b, d);
      mesh.add_face(a, b, c);
      mesh.add_face(a, c, d);
    }
  }
}

std::function<bool(double, double)> disk(double cx, double cy, double r) {
  return [=](double x, double y) { return std::hypot(x - cx, y - cy) < r; };
}
std::function<bool(double, double)> box(double x0, double x1, double y0, double y1) {
  return [=](double x, double y) { return x > x0 && x < x1 && y > y0 && y < y1; };
}

// The id of the hole whose centroid is nearest `p`, among those of fewer than 60 edges (a
// sheet's border has its centroid in the sheet's middle too).
int hole_near(const std::vector<Hole>& holes, const Point& p) {
  int best = -1;
  for (const auto& hole : holes) {
    if (hole.size() >= 60) continue;
    if (best < 0 || (hole.centroid - p).norm() < (holes[best].centroid - p).norm()) best = hole.id;
  }
  return best;
}

// Fills with the given bridges and checks the guarantees every bridge keeps.
HoleFill bridge_and_check(const Mesh& before, Mesh& after, std::pair<int, int> bridge) {
  const auto holes = find_holes(before);
  after = before;
  HoleSelection selection;
  selection.hole_ids = {bridge.first};
  selection.bridges = {bridge};
  const auto fills = fill_holes(after, holes, {}, selection);
  EXPECT_EQ(fills.size(), 1u);
  if (fills.empty()) return {};
  EXPECT_FALSE(fills[0].failed()) << fills[0].failure;
  EXPECT_EQ(fills[0].joined_holes, std::vector<int>{bridge.second});
  EXPECT_EQ(fills[0].self_intersections, 0u);
  EXPECT_EQ(count_patch_intersections(after, fills[0].patch), 0u);
  EXPECT_EQ(connected_components(after), 1u);
  EXPECT_TRUE(is_oriented_manifold(after));
  EXPECT_TRUE(original_part_unchanged(before, after));
  return fills[0];
}

// The viewer steps a joined fill one stage at a time (advance_joined); fill_holes plans and adds
// it in one go: both make the very same mesh, and the steps report the stages in order.
TEST(Bridge, AdvancingJoinedLoopsStageByStageMakesWhatFillHolesMakes) {
  const Mesh before = capsule_without([](const Point& c) { return std::abs(c[2]) < 0.5; });
  const auto holes = find_holes(before);
  ASSERT_EQ(holes.size(), 2u);
  Mesh stepped = before;
  HoleFill fill;
  for (const Stage stage : {Stage::Triangulated, Stage::Refined, Stage::Smoothed}) {
    ASSERT_EQ(advance_joined(stepped, {&holes[0], &holes[1]}, fill, {}), StageRun::Ran)
        << fill.failure;
    EXPECT_EQ(fill.stage(), stage);
  }
  EXPECT_EQ(advance_joined(stepped, {&holes[0], &holes[1]}, fill, {}), StageRun::AllDone);
  EXPECT_EQ(fill.joined_holes, std::vector<int>{1});
  EXPECT_EQ(fill.boundary_edges, holes[0].size() + holes[1].size());
  Mesh direct = before;
  HoleSelection selection;
  selection.bridges = {{0, 1}};
  fill_holes(direct, holes, {}, selection);
  ASSERT_EQ(stepped.n_vertices(), direct.n_vertices());
  ASSERT_EQ(stepped.n_faces(), direct.n_faces());
  for (const auto v : stepped.vertices()) EXPECT_EQ(stepped.point(v), direct.point(v));
}

TEST(Bridge, SpliceVisitsTheBridgeEndsTwice) {
  Hole outer, inner;
  for (int i = 0; i < 4; ++i) {
    outer.vertices.emplace_back(i);
    outer.halfedges.emplace_back(2 * i);
  }
  for (int i = 0; i < 3; ++i) {
    inner.vertices.emplace_back(10 + i);
    inner.halfedges.emplace_back(20 + 2 * i);
  }
  const Hole joined = splice_loop(outer, inner, 1, 2);
  std::vector<int> ids;
  for (const auto v : joined.vertices) ids.push_back(v.idx());
  EXPECT_EQ(ids, (std::vector<int>{0, 1, 12, 10, 11, 12, 1, 2, 3}));
  EXPECT_FALSE(joined.halfedges[1].is_valid());  // 1 -> 12, the bridge
  EXPECT_FALSE(joined.halfedges[5].is_valid());  // 12 -> 1, back over it
  EXPECT_EQ(joined.halfedges[4].idx(), 22);      // 11 -> 12 along the inner loop
}

TEST(Bridge, ARepeatedChordBetweenCopiesIsNotManifold) {
  Hole polygon;
  for (const int id : {0, 1, 12, 10, 11, 12, 1, 2, 3}) polygon.vertices.emplace_back(id);
  // Chords (3 -> 1) and (1 -> 3) through both copies of vertex 1: the same edge four times.
  EXPECT_FALSE(is_manifold_triangulation(polygon, {{0, 1, 8}, {1, 7, 8}, {6, 7, 8}}));
  EXPECT_TRUE(is_manifold_triangulation(polygon, {{0, 1, 8}, {1, 2, 8}}));
}

TEST(Bridge, JoinsACapsuleCutInTwoIntoOneClosedSurface) {
  const Mesh before = capsule_without([](const Point& c) { return std::abs(c[2]) < 0.5; });
  ASSERT_EQ(connected_components(before), 2u);
  Mesh after;
  const HoleFill fill = bridge_and_check(before, after, {0, 1});
  EXPECT_TRUE(find_holes(after).empty());
  EXPECT_EQ(euler_characteristic(after), 2);  // a sphere again, not a torus
  // The umbrella operator pulls the band toward a membrane (a catenoid between the two circles
  // sags by 0.13 in the middle); fairing continues the ellipsoid.
  EXPECT_LT(farthest_from_capsule(after, fill), 0.08);
  FillOptions fair;
  fair.smooth.method = SmoothMethod::Fair;
  Mesh faired = before;
  HoleSelection selection;
  selection.bridges = {{0, 1}};
  const auto fills = fill_holes(faired, find_holes(before), fair, selection);
  ASSERT_EQ(fills.size(), 1u);
  EXPECT_LT(farthest_from_capsule(faired, fills[0]), 0.02);
}

TEST(Bridge, JoinsATubeCutInTwo) {
  const Mesh before = testing::tube_cut_in_two(32, 40, 18, 22);
  const auto holes = find_holes(before);
  ASSERT_EQ(holes.size(), 4u);
  Mesh after;
  bridge_and_check(before, after,
                   {hole_near(holes, Point(0, 0, 1.8)), hole_near(holes, Point(0, 0, 2.2))});
  EXPECT_EQ(find_holes(after).size(), 2u);  // the tube's two ends
  EXPECT_EQ(euler_characteristic(after), 0);
}

TEST(Bridge, JoinsTwoFacingSheetsThroughOffsetHoles) {
  Mesh before;
  add_sheet(before, Point(0, 0, 0), Point(1, 1, 0), 0.05, true, disk(0.5, 0.5, 0.2));
  add_sheet(before, Point(0, 0, 0.4), Point(1, 1, 0.4), 0.05, false, disk(0.62, 0.5, 0.2));
  before = without_isolated_vertices(before);
  const auto holes = find_holes(before);
  ASSERT_EQ(holes.size(), 4u);
  Mesh after;
  bridge_and_check(before, after,
                   {hole_near(holes, Point(0.5, 0.5, 0)), hole_near(holes, Point(0.62, 0.5, 0.4))});
  EXPECT_EQ(find_holes(after).size(), 2u);    // the sheets' borders
  EXPECT_EQ(euler_characteristic(after), 0);  // two annuli and a band: one tunnel
}

// Fills `selection` of `before` and expects every selected hole refused for `reason` and the
// mesh as it was.
void expect_refused(const Mesh& before, const HoleSelection& selection, FailureKind reason) {
  Mesh after = before;
  const auto fills = fill_holes(after, find_holes(before), {}, selection);
  ASSERT_FALSE(fills.empty());
  for (const auto& fill : fills) {
    EXPECT_TRUE(fill.failed());
    EXPECT_EQ(fill.failure.kind, reason) << fill.failure;
  }
  EXPECT_EQ(after.n_faces(), before.n_faces());
  EXPECT_EQ(after.n_vertices(), before.n_vertices());
  EXPECT_TRUE(original_part_unchanged(before, after));
}

TEST(Bridge, RefusesHolesTooFarApart) {
  const Mesh before = capsule_without([](const Point& c) { return std::abs(c[2]) < 1.7; });
  HoleSelection selection;
  selection.bridges = {{0, 1}};
  expect_refused(before, selection, FailureKind::BadBridge);
}

TEST(Bridge, AnIslandTouchingItsHoleIsLeftOutOfItAndNothingIsCutThrough) {
  Mesh before;
  add_sheet(before, Point(0, 0, 0), Point(1, 1, 0), 0.05, true, box(0.3, 0.7, 0.3, 0.7));
  add_sheet(before, Point(0.3, 0.4, 0), Point(0.5, 0.6, 0), 0.05, true, nullptr);
  before = without_isolated_vertices(before);
  const auto holes = find_holes(before);
  ASSERT_EQ(holes.size(), 3u);
  const int hole = hole_near(holes, Point(0.5, 0.5, 0)),
            island = hole_near(holes, Point(0.4, 0.5, 0));
  Mesh after = before;
  const auto fills = fill_holes(after, holes, {}, HoleSelection{{hole, island}, 0});
  ASSERT_EQ(fills.size(), 2u);  // each loop on its own, the note saying why
  for (const auto& fill : fills) {
    EXPECT_NE(fill.islands_note.find("touches its boundary"), std::string::npos)
        << fill.islands_note;
    // In the sheet's plane, the hole's cap would lie on the island and the island's on its own
    // back: both are left open as they were.
    EXPECT_TRUE(fill.failed());
    EXPECT_GT(fill.refused_intersections, 0u);
  }
  EXPECT_EQ(after.n_faces(), before.n_faces());
  EXPECT_TRUE(original_part_unchanged(before, after));
}

TEST(Bridge, EachHoleIsFilledWithoutAnIslandOfTwoHoles) {
  // Two sheets facing the same way, with overlapping holes, and a piece between them.
  Mesh before;
  add_sheet(before, Point(0, 0, 0), Point(1, 1, 0), 0.05, true, box(0.3, 0.7, 0.3, 0.7));
  add_sheet(before, Point(0, 0, 0.2), Point(1, 1, 0.2), 0.05, true, box(0.35, 0.75, 0.3, 0.7));
  add_sheet(before, Point(0.45, 0.4, 0.1), Point(0.6, 0.6, 0.1), 0.05, true, nullptr);
  before = without_isolated_vertices(before);
  const auto holes = find_holes(before);
  ASSERT_EQ(holes.size(), 5u);
  const int lower = hole_near(holes, Point(0.5, 0.5, 0)),
            upper = hole_near(holes, Point(0.55, 0.5, 0.2)),
            piece = hole_near(holes, Point(0.525, 0.5, 0.1));
  Mesh after = before;
  const auto fills = fill_holes(after, holes, {}, HoleSelection{{lower, upper, piece}, 0});
  ASSERT_EQ(fills.size(), 3u);
  for (const auto& fill : fills) {
    EXPECT_NE(fill.islands_note.find("an island of two holes"), std::string::npos)
        << fill.islands_note;
    EXPECT_TRUE(fill.joined_holes.empty());
    // The holes' caps lie in their sheets' planes, clear of the piece; the piece's rim has no cap
    // but its own back.
    EXPECT_EQ(fill.failed(), fill.hole_id == piece) << fill.hole_id << ": " << fill.failure;
    EXPECT_EQ(testing::exact_patch_intersections(after, fill.patch.faces), 0u);
  }
  EXPECT_TRUE(original_part_unchanged(before, after));
  EXPECT_EQ(find_holes(after).size(), 3u);  // the two sheets' borders and the piece's rim
}

}  // namespace
}  // namespace holefill
