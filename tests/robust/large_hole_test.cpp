// Large holes with a staircase border, as deleting a region of a scan's grid leaves them: the
// restricted search's chords follow the boundary, and the thin strips they leave between the
// steps and a chord across them can only fold. Such a triangulation is replaced by the full
// search's where the hole is small enough for it (RestrictedSearch::full_search_above_dihedral).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fill_guarantees.h"
#include "hole_triangulation.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "test_meshes.h"

namespace holefill::testing {
namespace {

constexpr double kRightAngle = std::numbers::pi / 2;

// A round hole of radius 0.3 cut from a wavy cells x cells grid (its outer border left out).
struct StaircaseHole {
  Mesh mesh;
  std::vector<Hole> holes;  // the round hole and the grid's outer border
  const Hole& round() const { return *round_hole; }
  const Hole* round_hole = nullptr;
};

StaircaseHole staircase_hole(int cells) {
  StaircaseHole result;
  result.mesh = without_faces(
      make_grid(cells, [](double x, double y) { return 0.05 * std::sin(6 * x) * std::cos(5 * y); }),
      [](const Point& c) { return std::hypot(c[0] - 0.5, c[1] - 0.5) < 0.3; });
  // The grid's outer border has the same centroid, and more edges.
  result.holes = find_holes(result.mesh);
  const auto smallest =
      std::min_element(result.holes.begin(), result.holes.end(),
                       [](const Hole& a, const Hole& b) { return a.size() < b.size(); });
  if (smallest != result.holes.end()) result.round_hole = &*smallest;
  return result;
}

// Options that send this hole through a restricted search whose pockets are as short, against
// the hole, as the default pockets are against a hole of a thousand edges.
TriangulateOptions restricted_for(const Hole& hole) {
  TriangulateOptions options;
  options.restricted.above_edges = hole.size() / 2;
  options.restricted.pocket_edges = 8;
  options.restricted.nearest_neighbours = 4;
  return options;
}

TEST(LargeHole, ARestrictedTriangulationThatFoldsIsReplacedByTheFullSearchs) {
  const StaircaseHole cut = staircase_hole(50);
  ASSERT_EQ(cut.holes.size(), 2u);
  const HolePolygon polygon = detail::hole_polygon(cut.mesh, cut.round());
  const TriangulateOptions options = restricted_for(cut.round());

  const auto restricted = triangulate_polygon_restricted(polygon, options);
  ASSERT_TRUE(restricted);
  // What makes this case: the restricted search alone folds.
  ASSERT_GT(restricted->quality.max_dihedral, kRightAngle);

  TriangulateOptions full_only = options;
  full_only.restricted.above_edges = 0;
  const auto full = triangulate_polygon(polygon, full_only);
  ASSERT_TRUE(full);
  EXPECT_LT(full->quality.max_dihedral, kRightAngle);

  const auto chosen = triangulate_polygon(polygon, options);
  ASSERT_TRUE(chosen);
  EXPECT_EQ(chosen->triangles, full->triangles);

  // Either switch keeps the restricted search's answer.
  TriangulateOptions never = options;
  never.restricted.full_search_above_dihedral = std::numbers::pi;
  EXPECT_EQ(triangulate_polygon(polygon, never)->triangles, restricted->triangles);
  TriangulateOptions no_fallback = options;
  no_fallback.restricted.full_search_fallback = false;
  EXPECT_EQ(triangulate_polygon(polygon, no_fallback)->triangles, restricted->triangles);
}

// What a user stepping through the stages sees after Triangulate: the restricted search alone
// folds here (175 degrees; refinement and smoothing happen to straighten it on this small hole,
// and on a 1,200-edge one refinement was undone because the fold made it cross the steps).
TEST(LargeHole, AStaircaseHoleAboveTheRestrictedThresholdIsTriangulatedWithoutFolds) {
  const StaircaseHole cut = staircase_hole(50);
  ASSERT_EQ(cut.holes.size(), 2u);
  FillOptions options;
  options.triangulate = restricted_for(cut.round());
  for (const Stage last : {Stage::Triangulated, Stage::Smoothed}) {
    options.last_stage = last;
    Mesh mesh = cut.mesh;
    const auto fills = fill_holes(mesh, cut.holes, options, {.hole_ids = {cut.round().id}});
    ASSERT_EQ(fills.size(), 1u);
    const HoleFill& fill = fills[0];
    ASSERT_FALSE(fill.failed()) << fill.failure;
    EXPECT_EQ(fill.self_intersections, 0u);
    EXPECT_TRUE(fill.refinement_note.empty()) << fill.refinement_note;
    // The grid's own dihedral angles reach about 20 degrees; a fold is near 180.
    EXPECT_LT(fill.stats.max_dihedral_deg, 45.0) << static_cast<int>(last);
    EXPECT_EQ(check_fill_guarantees(cut.mesh, cut.holes, mesh, fills), "");
  }
}

}  // namespace
}  // namespace holefill::testing
