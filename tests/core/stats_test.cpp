// Patch and mesh statistics against the same quantities computed another way: angles by the law
// of cosines, areas by Heron's formula, valences by counting neighbours, components by hand.
#include "holefill/stats.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <set>

#include "holefill/fill.h"
#include "holefill/holes.h"
#include "test_meshes.h"

namespace holefill {
namespace {

using testing::append_mesh;
using testing::make_grid;
using testing::make_icosphere;
using testing::sphere_with_two_holes;

double angle_by_cosines(double opposite, double side1, double side2) {
  return std::acos(std::clamp(
      (side1 * side1 + side2 * side2 - opposite * opposite) / (2.0 * side1 * side2), -1.0, 1.0));
}

// The stats measured another way: angles by the law of cosines, areas by Heron's formula,
// dihedral angles by acos over the set of the patch faces' edges, valences by neighbours.
PatchStats measured_another_way(const Mesh& mesh, const Patch& patch) {
  PatchStats expected;
  for (const auto v : patch.new_vertices) {
    int neighbours = 0;
    for (const auto w : mesh.vv_range(v)) neighbours += w.is_valid() ? 1 : 0;
    ++expected.valence_histogram[neighbours];
  }
  double smallest = std::numbers::pi, sum_of_smallest = 0.0, largest_dihedral = 0.0;
  std::set<EdgeHandle> edges;
  for (const auto f : patch.faces) {
    std::vector<Point> p;
    for (const auto v : mesh.fv_range(f)) p.push_back(mesh.point(v));
    const double a = (p[1] - p[2]).norm(), b = (p[2] - p[0]).norm(), c = (p[0] - p[1]).norm();
    const double s = 0.5 * (a + b + c);
    expected.area += std::sqrt(s * (s - a) * (s - b) * (s - c));
    const double least =
        std::min({angle_by_cosines(a, b, c), angle_by_cosines(b, c, a), angle_by_cosines(c, a, b)});
    smallest = std::min(smallest, least);
    sum_of_smallest += least;
    for (const auto e : mesh.fe_range(f)) edges.insert(e);
  }
  for (const EdgeHandle e : edges) {
    const auto f0 = mesh.face_handle(mesh.halfedge_handle(e, 0));
    const auto f1 = mesh.face_handle(mesh.halfedge_handle(e, 1));
    if (!f0.is_valid() || !f1.is_valid()) continue;  // the mesh's border
    const Point n0 = mesh.calc_face_normal(f0), n1 = mesh.calc_face_normal(f1);
    largest_dihedral = std::max(largest_dihedral, std::acos(std::clamp(n0 | n1, -1.0, 1.0)));
  }
  const double degrees = 180.0 / std::numbers::pi;
  expected.min_angle_deg = smallest * degrees;
  expected.mean_min_angle_deg = sum_of_smallest / static_cast<double>(patch.faces.size()) * degrees;
  expected.max_dihedral_deg = largest_dihedral * degrees;
  return expected;
}

void expect_near(const PatchStats& stats, const PatchStats& expected) {
  EXPECT_EQ(stats.valence_histogram, expected.valence_histogram);
  EXPECT_NEAR(stats.min_angle_deg, expected.min_angle_deg, 1e-6);
  EXPECT_NEAR(stats.mean_min_angle_deg, expected.mean_min_angle_deg, 1e-6);
  EXPECT_NEAR(stats.max_dihedral_deg, expected.max_dihedral_deg, 1e-6);
  EXPECT_NEAR(stats.area, expected.area, 1e-9 * expected.area);
}

TEST(Stats, PatchStatsAgreeWithTheLawOfCosinesHeronAndCountedNeighbours) {
  Mesh mesh = sphere_with_two_holes();
  const auto holes = find_holes(mesh);
  const HoleFill fill = fill_hole(mesh, holes[0], FillOptions{});
  ASSERT_FALSE(fill.failed());
  const PatchStats stats = patch_stats(mesh, fill.patch);
  EXPECT_EQ(stats.new_vertices, fill.patch.new_vertices.size());
  EXPECT_EQ(stats.new_faces, fill.patch.faces.size());
  expect_near(stats, measured_another_way(mesh, fill.patch));
  EXPECT_GT(stats.min_angle_deg, 0.0);
}

// A patch of 25,000 faces in no particular order (several blocks of faces), beside faces that
// are not the patch's, measured on 1, 2, 3 and more threads than blocks: the same figures to the
// bit, and those measured another way.
TEST(Stats, ALargePatchMeasuredOnAnyThreadsGivesTheSameStats) {
  const Mesh mesh = make_grid(
      130, [](double x, double y) { return 0.2 * std::sin(9.0 * x) * std::cos(7.0 * y); });
  Patch patch;
  for (const auto f : mesh.faces()) {
    if (mesh.calc_face_centroid(f)[0] < 0.75) patch.faces.push_back(f);
  }
  std::mt19937 rng(9);
  std::shuffle(patch.faces.begin(), patch.faces.end(), rng);
  for (const auto v : mesh.vertices()) {
    if (mesh.point(v)[0] < 0.5) patch.new_vertices.push_back(v);
  }
  ASSERT_GT(patch.faces.size(), 25000u);
  const PatchStats one = patch_stats(mesh, patch);
  expect_near(one, measured_another_way(mesh, patch));
  for (const unsigned threads : {1u, 2u, 3u, 1000u}) {
    const PatchStats many = patch_stats(mesh, patch, threads);
    EXPECT_EQ(many.valence_histogram, one.valence_histogram);
    EXPECT_EQ(many.new_faces, one.new_faces);
    EXPECT_EQ(many.new_vertices, one.new_vertices);
    EXPECT_EQ(std::memcmp(&many.min_angle_deg, &one.min_angle_deg, sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&many.mean_min_angle_deg, &one.mean_min_angle_deg, sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&many.max_dihedral_deg, &one.max_dihedral_deg, sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&many.area, &one.area, sizeof(double)), 0) << threads << " threads";
  }
}

TEST(Stats, AnIcospheresValencesAreTwelveFivesAndTheRestSixes) {
  for (const int levels : {1, 2, 3}) {
    const Mesh sphere = make_icosphere(levels);
    const std::size_t vertices = 10 * (std::size_t{1} << (2 * levels)) + 2;
    ASSERT_EQ(sphere.n_vertices(), vertices);
    const std::map<int, std::size_t> expected{{5, 12}, {6, vertices - 12}};
    EXPECT_EQ(valence_histogram(sphere), expected) << levels;
  }
}

TEST(Stats, SurfaceCountsLeaveUnusedVerticesOutOfTheComponents) {
  // Unused vertices first, between pieces and last; two spheres and a triangle: three pieces of
  // surface whatever the unused vertices' order, while connected_components counts each of them.
  Mesh mesh;
  Mesh triangle;
  triangle.add_face(triangle.add_vertex(Point(0, 0, 0)), triangle.add_vertex(Point(1, 0, 0)),
                    triangle.add_vertex(Point(0, 1, 0)));
  mesh.add_vertex(Point(9, 9, 9));
  mesh.add_vertex(Point(8, 9, 9));
  append_mesh(mesh, make_icosphere(1), Point(0, 0, 0));
  mesh.add_vertex(Point(7, 9, 9));
  append_mesh(mesh, triangle, Point(5, 0, 0));
  append_mesh(mesh, make_icosphere(1), Point(0, 5, 0));
  mesh.add_vertex(Point(6, 9, 9));
  const SurfaceCounts counts = surface_counts(mesh);
  EXPECT_EQ(counts.components, 3u);
  EXPECT_EQ(counts.unused_vertices, 4u);
  EXPECT_EQ(connected_components(mesh), 7u);
  EXPECT_EQ(surface_counts(Mesh{}).components, 0u);
  EXPECT_EQ(surface_counts(make_icosphere(2)).components, 1u);
  EXPECT_EQ(surface_counts(make_icosphere(2)).unused_vertices, 0u);
}

TEST(Stats, ComponentsAreNumberedInTheOrderOfTheirFirstVertex) {
  // A lone vertex, a sphere, a triangle, another sphere: four components, labelled in that order.
  Mesh mesh;
  mesh.add_vertex(Point(9, 9, 9));
  const Mesh sphere = make_icosphere(1);
  Mesh triangle;
  triangle.add_face(triangle.add_vertex(Point(0, 0, 0)), triangle.add_vertex(Point(1, 0, 0)),
                    triangle.add_vertex(Point(0, 1, 0)));
  append_mesh(mesh, sphere, Point(0, 0, 0));
  append_mesh(mesh, triangle, Point(5, 0, 0));
  append_mesh(mesh, sphere, Point(0, 5, 0));
  EXPECT_EQ(connected_components(mesh), 4u);
  const std::vector<int> labels = component_labels(mesh);
  ASSERT_EQ(labels.size(), mesh.n_vertices());
  const std::size_t s = sphere.n_vertices();
  EXPECT_EQ(labels[0], 0);
  for (std::size_t i = 1; i <= s; ++i) EXPECT_EQ(labels[i], 1) << i;
  for (std::size_t i = s + 1; i <= s + 3; ++i) EXPECT_EQ(labels[i], 2) << i;
  for (std::size_t i = s + 4; i < labels.size(); ++i) EXPECT_EQ(labels[i], 3) << i;
  EXPECT_EQ(connected_components(Mesh{}), 0u);
}

}  // namespace
}  // namespace holefill
