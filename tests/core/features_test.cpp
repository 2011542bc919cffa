// Sharp features continued through holes (features.h, issue 35): a cube's edge and corner and a
// cylinder's rim restored against their analytic shapes; meshes without features filled exactly
// as with feature detection off.
#include "holefill/features.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <numbers>
#include <tuple>

#include "cad_parts.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "test_meshes.h"

namespace holefill {
namespace {

using testing::without_faces;

// The unit cube [0, 1]^3, ten grid squares (twenty triangles) along each edge.
Mesh unit_cube() {
  const auto lines = testing::grid_lines({{0.1, 10}});
  return testing::surface_of({lines, lines, lines, [](int, int, int) { return true; }});
}

// A cylinder of radius 1 around the z axis from z = 0 to z = 1, `around` vertices per ring, its
// flat caps in rings of the same count (a fan at the centre), outward oriented.
Mesh capped_cylinder(int around) {
  Mesh mesh;
  const int heights = 9, radii = 4;
  std::vector<std::vector<VertexHandle>> side(heights);
  auto ring_point = [&](double r, int i, double z) {
    const double a = 2.0 * std::numbers::pi * i / around;
    return Point(r * std::cos(a), r * std::sin(a), z);
  };
  for (int k = 0; k < heights; ++k) {
    for (int i = 0; i < around; ++i)
      side[k].push_back(mesh.add_vertex(ring_point(1.0, i, k / 8.0)));
  }
  for (int k = 0; k + 1 < heights; ++k) {
    for (int i = 0; i < around; ++i) {
      const int j = (i + 1) % around;
      mesh.add_face(side[k][i], side[k][j], side[k + 1][j]);
      mesh.add_face(side[k][i], side[k + 1][j], side[k + 1][i]);
    }
  }
  for (const bool top : {false, true}) {
    const double z = top ? 1.0 : 0.0;
    std::vector<std::vector<VertexHandle>> rings(radii + 1);
    rings[radii] = side[top ? heights - 1 : 0];
    for (int r = 1; r < radii; ++r) {
      for (int i = 0; i < around; ++i) {
        rings[r].push_back(mesh.add_vertex(ring_point(double(r) / radii, i, z)));
      }
    }
    const VertexHandle centre = mesh.add_vertex(Point(0.0, 0.0, z));
    auto face = [&](VertexHandle a, VertexHandle b, VertexHandle c) {
      top ? mesh.add_face(a, b, c) : mesh.add_face(a, c, b);
    };
    for (int i = 0; i < around; ++i) {
      const int j = (i + 1) % around;
      face(centre, rings[1][i], rings[1][j]);
      for (int r = 1; r < radii; ++r) {
        face(rings[r][i], rings[r + 1][i], rings[r + 1][j]);
        face(rings[r][i], rings[r + 1][j], rings[r][j]);
      }
    }
  }
  return mesh;
}

std::vector<HoleFill> fill_all(Mesh& mesh, double feature_angle, FillOptions options = {}) {
  options.features.angle_degrees = feature_angle;
  return fill_holes(mesh, find_holes(mesh), options);
}

// The angle between the normals of the two faces at the edge from a to b (radians).
double dihedral_at(const Mesh& mesh, VertexHandle a, VertexHandle b) {
  for (const auto h : mesh.voh_range(a)) {
    if (mesh.to_vertex_handle(h) != b) continue;
    const Point n0 = mesh.calc_face_normal(mesh.face_handle(h));
    const Point n1 = mesh.calc_face_normal(mesh.opposite_face_handle(h));
    return std::atan2(OpenMesh::cross(n0, n1).norm(), OpenMesh::dot(n0, n1));
  }
  ADD_FAILURE() << "no edge between the crease's vertices";
  return 0.0;
}

// Fills the mesh's one hole with features on, checking what every such fill must hold: the hole
// closed without a note, the original part kept, the patch manifold and clear of the mesh.
HoleFill fill_the_hole(Mesh& mesh, const FillOptions& options = {}) {
  const Mesh before = mesh;
  const auto fills = fill_all(mesh, 40.0, options);
  EXPECT_EQ(fills.size(), 1u);
  if (fills.empty()) return {};
  const HoleFill& fill = fills[0];
  EXPECT_FALSE(fill.failed()) << fill.failure;
  EXPECT_TRUE(fill.features_note.empty()) << fill.features_note;
  EXPECT_TRUE(testing::original_part_unchanged(before, mesh));
  EXPECT_TRUE(testing::is_oriented_manifold(mesh));
  EXPECT_TRUE(find_holes(mesh).empty());
  EXPECT_EQ(count_patch_intersections(mesh, fill.patch), 0u);
  return fill;
}

bool same_mesh(const Mesh& a, const Mesh& b) {
  return a.n_vertices() == b.n_vertices() && a.n_faces() == b.n_faces() &&
         testing::original_part_unchanged(a, b);
}

double in_degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

TEST(Features, CubeEdgeIsRestoredStraightAndSharp) {
  const Mesh cube = unit_cube();
  Mesh mesh =
      without_faces(cube, [](const Point& c) { return (c - Point(0.5, 0, 0)).norm() < 0.25; });
  const HoleFill fill = fill_the_hole(mesh);
  ASSERT_EQ(fill.features.lines.size(), 2u);
  ASSERT_EQ(fill.features.junctions.size(), 1u);
  EXPECT_FALSE(fill.features.junctions[0].corner);
  ASSERT_EQ(fill.creases.size(), 1u);
  // Every new vertex on one of the two faces of the cube that meet at the edge.
  for (const auto v : fill.patch.new_vertices) {
    const Point& p = mesh.point(v);
    EXPECT_TRUE(std::abs(p[1]) < 1e-9 || std::abs(p[2]) < 1e-9) << p;
    EXPECT_GT(p[0], 0.0);
    EXPECT_LT(p[0], 1.0);
  }
  // The crease on the cube's edge (y = z = 0), between its faces at 90 degrees.
  const auto& crease = fill.creases[0];
  ASSERT_GE(crease.size(), 4u);
  for (std::size_t i = 0; i < crease.size(); ++i) {
    const Point& p = mesh.point(crease[i]);
    EXPECT_NEAR(p[1], 0.0, 1e-12);
    EXPECT_NEAR(p[2], 0.0, 1e-12);
    if (i > 0) {
      EXPECT_NEAR(in_degrees(dihedral_at(mesh, crease[i - 1], crease[i])), 90.0, 1e-9);
    }
  }
}

TEST(Features, CubeCornerIsRestoredAtTheTrueCorner) {
  const Mesh cube = unit_cube();
  Mesh mesh = without_faces(cube, [](const Point& c) { return c.norm() < 0.3; });
  const HoleFill fill = fill_the_hole(mesh);
  ASSERT_EQ(fill.features.junctions.size(), 1u);
  ASSERT_TRUE(fill.features.junctions[0].corner);
  EXPECT_LT(fill.features.junctions[0].corner_point.norm(), 1e-12);
  ASSERT_EQ(fill.creases.size(), 3u);
  // The three chains meet at one new vertex at the corner.
  const VertexHandle corner = fill.creases[0].back();
  EXPECT_LT(mesh.point(corner).norm(), 1e-12);
  for (const auto& chain : fill.creases) {
    EXPECT_EQ(chain.back(), corner);
    for (std::size_t i = 1; i < chain.size(); ++i) {
      EXPECT_NEAR(in_degrees(dihedral_at(mesh, chain[i - 1], chain[i])), 90.0, 1e-9);
    }
  }
  // Three planar faces: every patch face lies in one of the planes x = 0, y = 0, z = 0.
  for (const auto f : fill.patch.faces) {
    const Point n = mesh.calc_face_normal(f);
    EXPECT_NEAR(std::max({std::abs(n[0]), std::abs(n[1]), std::abs(n[2])}), 1.0, 1e-9);
    int on_plane[3] = {0, 0, 0};
    for (const auto v : mesh.fv_range(f)) {
      for (int axis = 0; axis < 3; ++axis) on_plane[axis] += std::abs(mesh.point(v)[axis]) < 1e-9;
    }
    EXPECT_TRUE(on_plane[0] == 3 || on_plane[1] == 3 || on_plane[2] == 3);
  }
}

// The rim of a cylinder (48 vertices around) through a hole across it: the new rim vertices on
// the true circle, the rim's dihedral near 90 degrees (nearer when faired, which keeps the side
// cylindrical), the cap's part of the patch on the cap's plane.
TEST(Features, CylinderRimFollowsTheCircle) {
  FillOptions faired;
  faired.smooth.method = SmoothMethod::Fair;
  faired.smooth.fair.order = 3;
  for (const auto& [options, dihedral_error, side_error] :
       {std::tuple{FillOptions{}, 10.0, 0.02}, std::tuple{faired, 2.0, 0.005}}) {
    Mesh mesh = without_faces(capped_cylinder(48),
                              [](const Point& c) { return (c - Point(1, 0, 1)).norm() < 0.35; });
    const HoleFill fill = fill_the_hole(mesh, options);
    ASSERT_EQ(fill.creases.size(), 1u);
    const auto& rim = fill.creases[0];
    ASSERT_GE(rim.size(), 4u);
    double worst_radius = 0.0, worst_dihedral = 0.0, worst_side = 0.0;
    for (std::size_t i = 0; i < rim.size(); ++i) {
      const Point& p = mesh.point(rim[i]);
      EXPECT_NEAR(p[2], 1.0, 1e-12);
      worst_radius = std::max(worst_radius, std::abs(std::hypot(p[0], p[1]) - 1.0));
      if (i > 0) {
        const double angle = in_degrees(dihedral_at(mesh, rim[i - 1], rim[i]));
        worst_dihedral = std::max(worst_dihedral, std::abs(angle - 90.0));
      }
    }
    EXPECT_LT(worst_radius, 2e-4);
    EXPECT_LT(worst_dihedral, dihedral_error);
    for (const auto v : fill.patch.new_vertices) {
      const Point& p = mesh.point(v);
      if (std::abs(p[2] - 1.0) < 1e-9) continue;  // on the cap's plane
      worst_side = std::max(worst_side, std::abs(std::hypot(p[0], p[1]) - 1.0));
    }
    EXPECT_LT(worst_side, side_error);
  }
}

TEST(Features, MeshesWithoutFeaturesAreFilledAsWithDetectionOff) {
  for (const char* file : {"bunny.obj", "sphere.obj", "torus.obj", "heart.obj"}) {
    const Mesh original = load_mesh(std::filesystem::path(HOLEFILL_ASSETS_DIR) / file);
    Mesh with = original, without = original;
    const auto fills = fill_all(with, 40.0);
    fill_all(without, 0.0);
    EXPECT_TRUE(same_mesh(with, without)) << file;
    for (const auto& fill : fills) EXPECT_TRUE(fill.creases.empty()) << file;
  }
}

// A ridge along y = 1/2, sharp (90 degrees) for x < 0.4 and rounded over (radius 0.2) from
// x = 0.6 on: one feature line enters the hole and none leaves.
TEST(Features, AnUnmatchedLineFallsBackToThePlainFillWithANote) {
  const auto ridge = [](double x, double y) {
    const double s = std::clamp((x - 0.4) / 0.2, 0.0, 1.0);
    const double r = 0.2 * s * s * (3.0 - 2.0 * s);
    return std::hypot(y - 0.5, r) - r;
  };
  const Mesh grid = testing::make_grid(21, ridge);
  const auto cut = [](const Point& c) { return std::hypot(c[0] - 0.5, c[1] - 0.5) < 0.15; };
  Mesh with = without_faces(grid, cut), without = with;
  const auto fills = fill_all(with, 40.0);
  fill_all(without, 0.0);
  // The hole, not the grid's border.
  const auto hole = std::min_element(fills.begin(), fills.end(), [](const auto& a, const auto& b) {
    return a.boundary_edges < b.boundary_edges;
  });
  ASSERT_NE(hole, fills.end());
  EXPECT_EQ(hole->features.lines.size(), 1u);
  EXPECT_TRUE(hole->creases.empty());
  EXPECT_NE(hole->features_note.find("no partner"), std::string::npos) << hole->features_note;
  EXPECT_TRUE(same_mesh(with, without));
}

TEST(Features, DetectionIsOffAtAngleZero) {
  Mesh mesh = without_faces(unit_cube(),
                            [](const Point& c) { return (c - Point(0.5, 0, 0)).norm() < 0.25; });
  const auto holes = find_holes(mesh);
  ASSERT_EQ(holes.size(), 1u);
  EXPECT_TRUE(find_hole_features(mesh, holes[0], {0.0}).lines.empty());
  EXPECT_EQ(find_hole_features(mesh, holes[0], {40.0}).lines.size(), 2u);
  // At 95 degrees the cube's 90-degree edges are not sharp.
  EXPECT_TRUE(find_hole_features(mesh, holes[0], {95.0}).lines.empty());
}

}  // namespace
}  // namespace holefill
