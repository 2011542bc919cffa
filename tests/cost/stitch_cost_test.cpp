// Stitching costs time and memory linear in the boundary whatever the tolerance (issue 32, #1):
// every boundary point listed every point within the tolerance, so --stitch-tolerance 1e10 on
// a 60,000-face grid exported triangle by triangle took 154 s and 19 GB, and a tolerance of 1
// ran out of 4 GB after 109 s. Each point's partners are now looked for among its
// kMostPointsWithin nearest; a point with more has its edges left apart, counted.
#include <gtest/gtest.h>

#include "holefill/holes.h"
#include "holefill/prepare.h"
#include "holefill/stitch.h"
#include "holefill/weld.h"

namespace holefill::testing {
namespace {

// A unit square of n x n cells, two triangles each, every triangle on its own three vertices.
Mesh triangle_by_triangle_grid(int n) {
  Mesh mesh;
  const double s = 1.0 / n;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Point a(i * s, j * s, 0.0), b((i + 1) * s, j * s, 0.0),
          c((i + 1) * s, (j + 1) * s, 0.0), d(i * s, (j + 1) * s, 0.0);
      mesh.add_face(mesh.add_vertex(a), mesh.add_vertex(b), mesh.add_vertex(c));
      mesh.add_face(mesh.add_vertex(a), mesh.add_vertex(c), mesh.add_vertex(d));
    }
  }
  return mesh;
}

TEST(StitchCost, AToleranceFarAboveTheEdgesLeavesEveryEdgeApartAtOnce) {
  constexpr int kCells = 173;  // 59,858 triangles
  const Mesh grid = triangle_by_triangle_grid(kCells);
  const std::size_t boundary_edges = 3 * grid.n_faces();
  for (const double tolerance : {1e10, 1.0, 3.0 / kCells}) {
    SCOPED_TRACE(tolerance);
    Mesh mesh = grid;
    const StitchReport report = stitch_borders(mesh, {tolerance});
    EXPECT_EQ(report.edges_stitched, 0u);
    EXPECT_EQ(report.edges_left_apart, boundary_edges);
    EXPECT_EQ(mesh.n_vertices(), grid.n_vertices());  // nothing merged
  }
  // Within the spacing every seam closes: one flat square, its rim the only loop.
  Mesh mesh = grid;
  const StitchReport report = stitch_borders(mesh, {0.3 / kCells});
  EXPECT_EQ(report.edges_stitched, (boundary_edges - 4 * kCells) / 2);
  EXPECT_EQ(report.edges_left_apart, 0u);
  EXPECT_EQ(mesh.n_vertices(), static_cast<std::size_t>((kCells + 1) * (kCells + 1)));
  EXPECT_EQ(find_holes(mesh).size(), 1u);
}

// Welding looks at each boundary point's few nearest only: a tolerance far above the edges made
// every point search every other (650 s for this grid through holefill info).
TEST(StitchCost, WeldingAndTheWholePreparationStayLinearWhateverTheTolerance) {
  constexpr int kCells = 173;
  const Mesh grid = triangle_by_triangle_grid(kCells);
  for (const double tolerance : {1e10, 1.0, 0.0}) {
    SCOPED_TRACE(tolerance);
    Mesh mesh = grid;
    EXPECT_EQ(weld_touching_vertices(mesh, tolerance).positions, 0u);  // crowded, or one piece each
    EXPECT_EQ(mesh.n_vertices(), grid.n_vertices());
    PrepareOptions options;
    options.stitch_options.tolerance = tolerance;
    mesh = grid;
    EXPECT_EQ(prepare_mesh(mesh, options).weld.positions, 0u);
  }
}

// N lone slivers one above the other, each a unit long base under an apex at its middle: the
// ball around each base holds about half of all apexes (none within the tolerance of any base).
Mesh stacked_slivers(int n) {
  Mesh mesh;
  constexpr double kStep = 1e-5, kHeight = 0.005 + 0.5 * kStep;
  for (int i = 0; i < n; ++i) {
    const double y = i * kStep;
    mesh.add_face(mesh.add_vertex(Point(0.0, y, 0.0)), mesh.add_vertex(Point(1.0, y, 0.0)),
                  mesh.add_vertex(Point(0.5, y + kHeight, 0.0)));
  }
  return mesh;
}

// The T-junction search looks at about as many points as lie near each boundary edge: it looked at
// every point in the ball around the edge, N^2 / 2 on these slivers.
TEST(StitchCost, LongEdgesAcrossADenseBoundaryAreSearchedAlongTheirLength) {
  constexpr int kSlivers = 100000;
  Mesh mesh = stacked_slivers(kSlivers);
  const StitchReport report = stitch_borders(mesh);
  EXPECT_EQ(report.t_junctions, 0u);
  EXPECT_EQ(report.edges_stitched, 0u);
  EXPECT_EQ(mesh.n_vertices(), 3u * kSlivers);
}

}  // namespace
}  // namespace holefill::testing
