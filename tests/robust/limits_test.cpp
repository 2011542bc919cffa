// Bounded work and limits that say what they are: a large --tau is capped against the
// boundary's density instead of running for minutes, and a hole too large for the dynamic
// program is refused with the limit that applies to it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cad_parts.h"
#include "fill_guarantees.h"
#include "hole_triangulation.h"
#include "holefill/borders.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "test_meshes.h"

namespace holefill::testing {
namespace {

using detail::kMaxVertexPasses;
using detail::plan_triangulation;

// A unit cube without its top face: a hole of 4 edges.
Mesh open_cube() {
  const Mesh cube = surface_of({{0, 1}, {0, 1}, {0, 1}, [](int, int, int) { return true; }});
  return without_faces(cube, [](const Point& c) { return c[2] > 0.99; });
}

TEST(Limits, ALargeTauStopsAtTheDensityCapAndSaysSo) {
  // tau 100 asks for about (100 / sqrt 2)^2 = 5,000 times the boundary's density (thousands of
  // vertices on this hole; tau 1000 ran for 300 s); the cap stops it at 32 times.
  const Mesh before = open_cube();
  const auto holes = find_holes(before);
  ASSERT_EQ(holes.size(), 1u);
  ASSERT_EQ(holes[0].size(), 4u);
  Mesh mesh = before;
  FillOptions options;
  options.refine.tau = 100.0;
  const auto fills = fill_holes(mesh, holes, options);
  ASSERT_EQ(fills.size(), 1u);
  const HoleFill& fill = fills[0];
  EXPECT_TRUE(fill.refinement.stopped_at_vertex_cap);
  // Area 1 over the mean boundary scale squared (edges of length 1 and sqrt 2), times 32.
  EXPECT_GE(fill.refinement.vertex_cap, 16u);
  EXPECT_LE(fill.refinement.vertex_cap, 32u);
  EXPECT_LE(fill.stats.new_vertices, fill.refinement.vertex_cap);
  EXPECT_NE(fill.refinement_note.find("cap of " + std::to_string(fill.refinement.vertex_cap)),
            std::string::npos)
      << fill.refinement_note;
  EXPECT_EQ(check_fill_guarantees(before, holes, mesh, fills), "");

  // The paper's tau stays far below the cap.
  Mesh plain = before;
  const auto plain_fills = fill_holes(plain, holes, {});
  EXPECT_FALSE(plain_fills[0].refinement.stopped_at_vertex_cap);
  EXPECT_TRUE(plain_fills[0].refinement_note.empty()) << plain_fills[0].refinement_note;
}

TEST(Limits, AHoleTooLargeForTheDynamicProgramNamesItsLimit) {
  // 65,535 edges were refused with "at most 3000", the full search's limit, although the
  // restricted search runs on holes of that size: the limit that applies is the apex index's.
  const Mesh mesh = open_cube();
  Hole huge;
  huge.id = 0;
  huge.vertices.assign(kMaxPolygonSize, VertexHandle(0));
  huge.halfedges.assign(kMaxPolygonSize, HalfedgeHandle(0));
  const auto plan = plan_triangulation(mesh, huge, {});
  EXPECT_FALSE(plan.triangulation);
  EXPECT_EQ(plan.failure.kind, FailureKind::TooManyEdges) << plan.failure;
  // The limit named is the dynamic program's, not the full search's.
  const std::string& said = plan.failure.message;
  EXPECT_NE(said.find("at most " + std::to_string(kMaxPolygonSize - 1)), std::string::npos)
      << plan.failure;
  EXPECT_EQ(said.find("at most " + std::to_string(kMaxFullSearchEdges)), std::string::npos)
      << plan.failure;

  // Without the restricted search, the full search's limit is the one named.
  Hole large = huge;
  large.vertices.resize(kMaxFullSearchEdges + 1);
  large.halfedges.resize(kMaxFullSearchEdges + 1);
  TriangulateOptions full_only;
  full_only.restricted.above_edges = 0;
  const auto full = plan_triangulation(mesh, large, full_only);
  EXPECT_EQ(full.failure.kind, FailureKind::TooManyEdges) << full.failure;
  EXPECT_NE(full.failure.message.find("at most " + std::to_string(kMaxFullSearchEdges)),
            std::string::npos)
      << full.failure;
}

TEST(Limits, TheRestrictedSearchJoinsEachVertexToFewChords) {
  // Every pair of anchors (every 24th vertex) was a chord: at 50,000 edges each anchor joined
  // 2,083 others and the search took 333 s. Pockets of anchors keep every vertex's chords few.
  constexpr int kEdges = 20000;
  HolePolygon polygon;
  for (int i = 0; i < kEdges; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / kEdges;
    polygon.points.emplace_back(std::cos(angle), std::sin(angle), 0.1 * std::sin(5.0 * angle));
    polygon.outside_normals.emplace_back(0.0, 0.0, 0.0);
  }
  const RestrictedSearch search;
  const auto chords = restricted_chords(polygon, search);
  std::vector<int> degree(kEdges, 0);
  for (const auto& [i, k] : chords) {
    ASSERT_LT(i, k);
    ++degree[i];
    ++degree[k];
  }
  const int most = *std::max_element(degree.begin(), degree.end());
  // A vertex in two pockets at each of three levels and among its nearest neighbours' choices.
  EXPECT_LE(most, 6 * search.pocket_edges + 4 * search.nearest_neighbours);
  EXPECT_LE(chords.size(), static_cast<std::size_t>(kEdges) * 2 * search.pocket_edges);
}

// n triangles around the origin sharing only it (vertex 0), each on two rim points of its own,
// heights varying so that no two lie in one plane.
Mesh fan_of_lone_triangles(int n) {
  Mesh mesh;
  const VertexHandle centre = mesh.add_vertex(Point(0.0, 0.0, 0.0));
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n, b = 2.0 * std::numbers::pi * (i + 0.5) / n;
    const VertexHandle p = mesh.add_vertex(Point(std::cos(a), std::sin(a), 0.01 * (i % 7)));
    const VertexHandle q = mesh.add_vertex(Point(std::cos(b), std::sin(b), 0.01 * (i % 5)));
    mesh.add_face(centre, p, q);
  }
  return mesh;
}

TEST(Limits, ALoopThroughOneVertexTooManyTimesIsRefusedNamingTheLimit) {
  // 5,000 lone triangles around one vertex make one 15,000-edge loop through it 5,000 times:
  // planned for 145 s in 3.3 GB into a patch crossing itself (exit 5). Refused at once now.
  for (const int n : {kMaxVertexPasses + 1, 5000}) {
    const Mesh before = fan_of_lone_triangles(n);
    const auto holes = find_holes(before);
    ASSERT_EQ(holes.size(), 1u);
    ASSERT_EQ(holes[0].size(), 3u * n);
    Mesh mesh = before;
    const auto fills = fill_holes(mesh, holes, {});
    ASSERT_EQ(fills.size(), 1u);
    EXPECT_EQ(fills[0].failure.kind, FailureKind::VertexPassedTooOften) << fills[0].failure;
    // The message names the vertex, its passes and the limit.
    EXPECT_NE(fills[0].failure.message.find("vertex 1 " + std::to_string(n) + " times"),
              std::string::npos)
        << fills[0].failure;
    EXPECT_EQ(check_fill_guarantees(before, holes, mesh, fills), "");
  }
  // At the limit the loop is planned as before (whatever the patch, no refusal for passes).
  const Mesh at_limit = fan_of_lone_triangles(kMaxVertexPasses);
  const auto plan = plan_triangulation(at_limit, find_holes(at_limit)[0], {});
  EXPECT_NE(plan.failure.kind, FailureKind::VertexPassedTooOften) << plan.failure;
}

// The mesh with every coordinate times 2^exponent (exact).
Mesh scaled_by_power_of_two(Mesh mesh, int exponent) {
  for (const auto v : mesh.vertices()) {
    const Point p = mesh.point(v);
    mesh.set_point(v, Point(std::ldexp(p[0], exponent), std::ldexp(p[1], exponent),
                            std::ldexp(p[2], exponent)));
  }
  return mesh;
}

TEST(Limits, DecisionsAndStatisticsDoNotDependOnTheScale) {
  // From about 1e78 squared lengths overflow: the bunny's and an open cube's widest loops were
  // "the rim of a flat piece" (left open, exit 0) and the patch angles read 90 / 180 degrees; at
  // 1e-100 areas underflowed and a hole was a "0 %" border.
  const std::filesystem::path assets(HOLEFILL_ASSETS_DIR);
  const Mesh bunny = load_mesh(assets / "bunny.obj");
  const Mesh cube = open_cube();
  for (const Mesh* mesh : {&bunny, &cube}) {
    const Mesh& original = *mesh;
    const auto holes = find_holes(original);
    const auto classes = classify_loops(original, holes, mesh_pieces(original));
    Mesh filled = original;
    const auto fills = fill_holes(filled, holes, {});
    for (const int exponent : {260, -333}) {  // 1.9e78 and 5.7e-101
      SCOPED_TRACE(exponent);
      const Mesh mesh = scaled_by_power_of_two(original, exponent);
      const auto scaled_holes = find_holes(mesh);
      ASSERT_EQ(scaled_holes.size(), holes.size());
      const auto scaled_classes = classify_loops(mesh, scaled_holes, mesh_pieces(mesh));
      for (std::size_t i = 0; i < holes.size(); ++i) {
        EXPECT_EQ(scaled_classes[i].kind, classes[i].kind) << i << ": " << scaled_classes[i].reason;
        EXPECT_EQ(scaled_classes[i].spanned_share, classes[i].spanned_share) << i;
      }
      Mesh scaled_filled = mesh;
      const auto scaled_fills = fill_holes(scaled_filled, scaled_holes, {});
      ASSERT_EQ(scaled_fills.size(), fills.size());
      for (std::size_t i = 0; i < fills.size(); ++i) {
        const PatchStats &a = fills[i].stats, &b = scaled_fills[i].stats;
        EXPECT_EQ(b.new_faces, a.new_faces) << i;
        EXPECT_EQ(b.min_angle_deg, a.min_angle_deg) << i;
        EXPECT_EQ(b.mean_min_angle_deg, a.mean_min_angle_deg) << i;
        // Normals come from the scaled points by a formula of their own (OpenMesh's would
        // overflow): the same angle up to rounding.
        EXPECT_NEAR(b.max_dihedral_deg, a.max_dihedral_deg, 1e-9) << i;
        EXPECT_DOUBLE_EQ(std::ldexp(b.area, -2 * exponent), a.area) << i;
      }
    }
  }
}

}  // namespace
}  // namespace holefill::testing
