// Patches that never cut the part: CAD-like parts with holes across sharp edges of thin
// walls, long thin slots and strongly non-planar boundaries. On these the weight's best
// triangulation cuts through the part (checked below with the avoidance off); with it on, every
// hole closes cleanly: manifold, oriented, originals bit for bit, no degenerate triangle, and no
// patch/mesh intersection, by the library's count and by an exact rational check.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "cad_parts.h"
#include "exact_intersections.h"
#include "fill_guarantees.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "test_meshes.h"

namespace holefill::testing {
namespace {

constexpr double kWall = 0.05, kCell = 0.1;

// A bent sheet (an L-bracket of wall thickness kWall, legs 1 long and 1 deep).
Mesh sheet_bracket() {
  return surface_of({grid_lines({{kWall, 1}, {kCell, 10}}), grid_lines({{kWall, 1}, {kCell, 10}}),
                     grid_lines({{kCell, 10}}),
                     [](int i, int j, int) { return i == 0 || j == 0; }});
}

// A closed hollow box (a cube of side 1.1 with walls kWall thick: outer and inner surface).
Mesh hollow_box() {
  constexpr int kLast = 11;
  const auto lines = grid_lines({{kWall, 1}, {kCell, 10}, {kWall, 1}});
  return surface_of({lines, lines, lines, [](int i, int j, int k) {
                       return i == 0 || j == 0 || k == 0 || i == kLast || j == kLast || k == kLast;
                     }});
}

// A flat plate 1 x 1 x kWall.
Mesh thin_plate() {
  return surface_of({grid_lines({{kCell, 10}}), grid_lines({{kCell, 10}}), grid_lines({{kWall, 1}}),
                     [](int, int, int) { return true; }});
}

bool faces_minus_x_or_y(const Point& normal) { return normal[0] < -0.5 || normal[1] < -0.5; }

struct CadCase {
  std::string name;
  std::function<Mesh()> make;
  bool cut_by_best_triangulation;  // the weight's best triangulation intersects the part
};

std::vector<CadCase> cad_cases() {
  std::vector<CadCase> cases;
  for (const double radius : {0.2, 0.3, 0.45}) {
    const std::string r = std::to_string(static_cast<int>(radius * 100));
    // Round holes across the outer bend of the sheet and across an outer edge of the hollow
    // box: chords from one face to the other pass through the inner wall.
    cases.push_back({"BracketOuterBend" + r,
                     [radius] {
                       return without_faces_where(
                           sheet_bracket(), [&](const Point& c, const Point& n) {
                             return faces_minus_x_or_y(n) && (c - Point(0, 0, 0.5)).norm() < radius;
                           });
                     },
                     true});
    cases.push_back(
        {"HollowBoxEdge" + r,
         [radius] {
           return without_faces_where(hollow_box(), [&](const Point& c, const Point& n) {
             return faces_minus_x_or_y(n) && (c - Point(0, 0, 0.55)).norm() < radius;
           });
         },
         true});
    // Across the inside of the bend the chords run through the air.
    cases.push_back(
        {"BracketInnerBend" + r,
         [radius] {
           return without_faces_where(sheet_bracket(), [&](const Point& c, const Point& n) {
             return (n[0] > 0.5 || n[1] > 0.5) && (c - Point(kWall, kWall, 0.5)).norm() < radius;
           });
         },
         false});
  }
  // A long thin slot along the outer bend.
  cases.push_back(
      {"BracketSlotAlongTheBend",
       [] {
         return without_faces_where(sheet_bracket(), [](const Point& c, const Point& n) {
           return faces_minus_x_or_y(n) && std::abs(c[2] - 0.5) < 0.35 && c[0] < 0.2 && c[1] < 0.2;
         });
       },
       true});
  // A hole that wraps the rim of a thin plate: top, rim and bottom (far from planar).
  cases.push_back({"PlateRimWrap",
                   [] {
                     return without_faces(thin_plate(), [](const Point& c) {
                       return (c - Point(0.5, 0, 0.5 * kWall)).norm() < 0.3;
                     });
                   },
                   false});
  return cases;
}

class CadParts : public ::testing::TestWithParam<std::tuple<CadCase, WeightKind>> {};

TEST_P(CadParts, HolesCloseWithoutCuttingThePart) {
  const auto& [cad, weight] = GetParam();
  const Mesh before = cad.make();
  const auto holes = find_holes(before);
  ASSERT_FALSE(holes.empty());
  FillOptions options;
  options.triangulate.weight = weight;

  Mesh unguarded = before;
  FillOptions without = options;
  without.avoid_intersections = false;
  without.allow_intersections = true;  // keep the best patch, to count its pairs
  without.features.angle_degrees = 0;  // the paper's patch (continued creases may avoid the cut)
  std::size_t pairs_without = 0;
  for (const auto& fill : fill_holes(unguarded, holes, without)) {
    pairs_without += fill.self_intersections;
  }
  EXPECT_EQ(pairs_without > 0, cad.cut_by_best_triangulation) << pairs_without;

  Mesh mesh = before;
  const auto fills = fill_holes(mesh, holes, options);
  ASSERT_EQ(fills.size(), holes.size());
  EXPECT_EQ(check_fill_guarantees(before, holes, mesh, fills), "");
  EXPECT_TRUE(find_holes(mesh).empty());
  for (const auto& fill : fills) {
    EXPECT_FALSE(fill.failed()) << fill.failure;
    EXPECT_EQ(fill.self_intersections, 0u) << "hole " << fill.hole_id;
    EXPECT_EQ(count_patch_intersections(mesh, fill.patch), 0u) << "hole " << fill.hole_id;
    EXPECT_EQ(exact_patch_intersections(mesh, fill.patch.faces), 0u) << "hole " << fill.hole_id;
    EXPECT_EQ(fill.avoidance.changed, fill.avoidance.first_pairs > 0);
  }
}

INSTANTIATE_TEST_SUITE_P(Parts, CadParts,
                         ::testing::Combine(::testing::ValuesIn(cad_cases()),
                                            ::testing::Values(WeightKind::MaxMin, WeightKind::Liepa,
                                                              WeightKind::Area)),
                         [](const auto& info) {
                           return std::get<0>(info.param).name + "_" +
                                  to_string(std::get<1>(info.param));
                         });

}  // namespace
}  // namespace holefill::testing
