// The CAD set of holefill-features: its meshes are closed, manifold and where their shapes say;
// each case's hole is one simple loop across the features it names; the measures give the truth
// its own crease and bound a crease moved by a known distance.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "cad_cases.h"
#include "cad_parts.h"
#include "cad_shapes.h"
#include "crease_measure.h"
#include "holefill/holes.h"
#include "test_meshes.h"

namespace holefill::features {
namespace {

double enclosed_volume(const Mesh& mesh) {
  double six_volume = 0.0;
  for (const auto f : mesh.faces()) {
    auto fv = mesh.cfv_iter(f);
    const Point a = mesh.point(*fv), b = mesh.point(*++fv), c = mesh.point(*++fv);
    six_volume += OpenMesh::dot(a, OpenMesh::cross(b, c));
  }
  return six_volume / 6.0;
}

long euler(const Mesh& mesh) {
  return static_cast<long>(mesh.n_vertices()) - static_cast<long>(mesh.n_edges()) +
         static_cast<long>(mesh.n_faces());
}

// The distinct unit normals (rounded) of the cut-away faces: how many faces of the part the
// hole spans.
std::size_t normals_cut(const CadCase& c, const quality::CutMesh& cut) {
  std::set<std::array<long, 3>> normals;
  for (const auto f : cut.holes.front().removed_faces) {
    const Point n = c.closed.calc_face_normal(f);
    normals.insert({std::lround(n[0] * 100), std::lround(n[1] * 100), std::lround(n[2] * 100)});
  }
  return normals.size();
}

CadCase case_named(const std::string& name) {
  for (auto& c : generated_cases()) {
    if (c.name == name) return c;
  }
  throw std::invalid_argument(name);
}

TEST(CadSet, MeshesAreClosedManifoldSpheres) {
  for (const auto& c : generated_cases()) {
    SCOPED_TRACE(c.name);
    EXPECT_TRUE(testing::is_oriented_manifold(c.closed));
    EXPECT_TRUE(find_holes(c.closed).empty());
    EXPECT_EQ(euler(c.closed), 2);              // every vertex used, genus 0
    EXPECT_GT(enclosed_volume(c.closed), 0.0);  // faces point outwards
  }
}

TEST(CadSet, ShapesHaveTheirVolumes) {
  EXPECT_NEAR(enclosed_volume(make_box(1.0, 16)), 8.0, 1e-9);
  EXPECT_NEAR(enclosed_volume(make_step_block(8)), 3.0, 1e-9);
  // The cylinder's sides are chords of its circle: the prism on the 64-gon, caps flat.
  const double polygon = 0.5 * 64 * std::sin(2.0 * std::numbers::pi / 64);
  EXPECT_NEAR(enclosed_volume(make_cylinder(1.0, 1.0, 64)), polygon * 2.0, 1e-9);
  // The rounded box lies within the solid: box + slabs + quarter cylinders + a ball.
  const double a = 0.7, r = 0.3;
  const double solid = 8 * a * a * a + 6 * 4 * a * a * r + 3 * 2 * a * std::numbers::pi * r * r +
                       4.0 / 3.0 * std::numbers::pi * r * r * r;
  const double rounded = enclosed_volume(make_rounded_box(a, r, 12, 4));
  EXPECT_LT(rounded, solid);
  EXPECT_GT(rounded, 0.99 * solid);
}

TEST(CadSet, RoundedBoxPointsLieOnTheFillets) {
  const double a = 0.7, r = 0.3;
  const Mesh mesh = make_rounded_box(a, r, 12, 4);
  for (const auto v : mesh.vertices()) {
    const Point p = mesh.point(v);
    Point nearest;
    for (int axis = 0; axis < 3; ++axis) nearest[axis] = std::clamp(p[axis], -a, a);
    EXPECT_NEAR((p - nearest).norm(), r, 1e-12);
  }
}

TEST(CadSet, EachCutIsOneSimpleLoopAcrossItsFeatures) {
  for (const auto& c : generated_cases()) {
    SCOPED_TRACE(c.name);
    const auto cut = cut_case(c);
    ASSERT_TRUE(cut.has_value());
    const auto loops = find_holes(cut->mesh);
    ASSERT_EQ(loops.size(), 1u);
    EXPECT_FALSE(loops[0].pinched);
    EXPECT_EQ(loops[0].repeated_vertices, 0u);
    EXPECT_TRUE(testing::is_oriented_manifold(cut->mesh));
    EXPECT_GT(cut->holes.front().removed_faces.size(), 20u);
  }
  // The holes span the faces they are meant to: one plane, two across an edge, three at a corner.
  auto planes = [](const std::string& name) {
    for (const auto& c : generated_cases()) {
      if (c.name == name) return normals_cut(c, *cut_case(c));
    }
    return std::size_t{0};
  };
  EXPECT_EQ(planes("box-face"), 1u);
  EXPECT_EQ(planes("box-edge"), 2u);
  EXPECT_EQ(planes("box-corner"), 3u);
  EXPECT_EQ(planes("step-concave"), 2u);
  EXPECT_EQ(planes("step-concave-wide"), 2u);
  // ... but its rim crosses the side face's two convex creases (x = 1 and z = 1 on y = 1) next
  // to the corner (1, 1, 1), where they meet the concave one.
  const CadCase wide = case_named("step-concave-wide");
  const auto wide_cut = cut_case(wide);
  ASSERT_TRUE(wide_cut);
  int on_convex_creases = 0;
  const auto wide_loops = find_holes(wide_cut->mesh);
  for (const auto v : wide_loops.front().vertices) {
    const Point p = wide.closed.point(v);
    if (p[1] != 1.0) continue;
    on_convex_creases += (p[0] == 1.0 && p[2] > 1.0) + (p[2] == 1.0 && p[0] > 1.0);
  }
  EXPECT_EQ(on_convex_creases, 2);
  EXPECT_EQ(planes("step-corner"), 3u);
  EXPECT_EQ(planes("step-mixed"), 3u);
}

TEST(CadSet, SplittingLongEdgesKeepsTheSurface) {
  Mesh mesh = make_box(1.0, 2);  // edges of 1 and sqrt(2)
  split_long_edges(mesh, 0.3);
  for (const auto e : mesh.edges()) EXPECT_LE(mesh.calc_edge_length(e), 0.3);
  EXPECT_TRUE(testing::is_oriented_manifold(mesh));
  EXPECT_NEAR(enclosed_volume(mesh), 8.0, 1e-9);
  for (const auto v : mesh.vertices()) {
    const Point p = mesh.point(v);
    EXPECT_NEAR(std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])}), 1.0, 1e-12);
  }
}

// The mean over the faces of each face's smallest angle, radians.
double mean_smallest_angle(const Mesh& mesh) {
  double sum = 0.0;
  for (const auto f : mesh.faces()) {
    double smallest = std::numbers::pi;
    for (const auto h : mesh.fh_range(f)) {
      const Point a = mesh.point(mesh.from_vertex_handle(h));
      const Point b = mesh.point(mesh.to_vertex_handle(h));
      const Point c = mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h)));
      smallest = std::min(
          smallest, std::atan2(OpenMesh::cross(a - c, b - c).norm(), OpenMesh::dot(a - c, b - c)));
    }
    sum += smallest;
  }
  return sum / static_cast<double>(mesh.n_faces());
}

TEST(CadSet, FlatFlipsKeepTheSurfaceAndMakeItDelaunay) {
  // A box whose faces are cut unevenly (x at -1, -0.95, 1): long thin triangles, split into
  // fans of thinner ones.
  Mesh mesh = testing::surface_of(
      {{-1.0, -0.95, 1.0}, {-1.0, 1.0}, {-1.0, 1.0}, [](int, int, int) { return true; }});
  split_long_edges(mesh, 0.3);
  const double before = mean_smallest_angle(mesh);
  const std::size_t vertices = mesh.n_vertices();
  flip_flat_edges_to_delaunay(mesh);
  EXPECT_TRUE(testing::is_oriented_manifold(mesh));
  EXPECT_EQ(mesh.n_vertices(), vertices);
  EXPECT_NEAR(enclosed_volume(mesh), 8.0, 1e-9);
  EXPECT_GT(mean_smallest_angle(mesh), before);
  // Delaunay: across every edge inside a face of the box, the opposite angles sum to at most 180.
  auto opposite = [&](HalfedgeHandle h) {
    const Point a = mesh.point(mesh.from_vertex_handle(h)),
                b = mesh.point(mesh.to_vertex_handle(h));
    const Point c = mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h)));
    return std::atan2(OpenMesh::cross(a - c, b - c).norm(), OpenMesh::dot(a - c, b - c));
  };
  std::size_t flat_edges = 0;
  for (const auto e : mesh.edges()) {
    const auto h = mesh.halfedge_handle(e, 0), g = mesh.halfedge_handle(e, 1);
    const Point n0 = mesh.calc_face_normal(mesh.face_handle(h));
    const Point n1 = mesh.calc_face_normal(mesh.face_handle(g));
    if (OpenMesh::dot(n0, n1) < 1.0 - 1e-12) continue;
    ++flat_edges;
    EXPECT_LE(opposite(h) + opposite(g), std::numbers::pi + 1e-9);
  }
  EXPECT_GT(flat_edges, 100u);
  // Every face still lies in one of the box's faces: no flip crossed an edge of the box.
  for (const auto f : mesh.faces()) {
    const Point n = mesh.calc_face_normal(f);
    EXPECT_NEAR(std::max({std::abs(n[0]), std::abs(n[1]), std::abs(n[2])}), 1.0, 1e-12);
  }
}

TEST(CadSet, RealCasesFindACreaseAndACorner) {
  const Mesh box = make_box(1.0, 8);
  const auto cases = real_cases("box", box, 30.0, 3.0, 1);
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_EQ(cases[0].name, "box-crease");
  EXPECT_EQ(cases[1].name, "box-corner");
  // A crease vertex has two coordinates at +-1, a corner vertex three.
  auto on_faces = [](const Point& p) {
    int n = 0;
    for (int axis = 0; axis < 3; ++axis) n += std::abs(std::abs(p[axis]) - 1.0) < 1e-12;
    return n;
  };
  EXPECT_EQ(on_faces(cases[0].center), 2);
  EXPECT_EQ(on_faces(cases[1].center), 3);
  for (const auto& c : cases) EXPECT_TRUE(cut_case(c).has_value());
}

// The cut-away faces themselves as the fill, in the closed mesh, with the hole's loop.
quality::FilledHole truth_patch(const quality::CutMesh& cut) {
  const auto& hole = cut.holes.front();
  return {find_holes(cut.mesh).front().vertices, hole.removed_faces, hole.inner_vertices};
}

TEST(CreaseMeasure, TheTruthCoversItselfAndKeepsItsCrease) {
  const CadCase c = case_named("box-edge");
  const auto cut = cut_case(c);
  ASSERT_TRUE(cut);
  const quality::Truth truth(c.closed);
  const auto q =
      measure_feature_fill(c.closed, truth, cut->holes.front(), c.closed, truth_patch(*cut), true);
  EXPECT_NEAR(q.cover_max, 0.0, 1e-12);
  EXPECT_NEAR(q.patch.max_distance, 0.0, 1e-12);
  ASSERT_GT(q.crease_samples, 0u);
  EXPECT_NEAR(q.crease_max, 0.0, 1e-12);
  EXPECT_NEAR(q.crease_dihedral, 90.0, 1e-9);
  EXPECT_NEAR(q.truth_dihedral, 90.0, 1e-9);
  EXPECT_TRUE(q.manifold);
  EXPECT_TRUE(q.closed);
  EXPECT_EQ(q.intersections, 0u);
}

TEST(CreaseMeasure, ACreasePushedInIsMissedByNoMoreThanThePush) {
  // The box's edge x = z = 1 inside the hole moved a distance `push` toward the box's axis: the
  // fill is bevelled there, the true crease lies at most `push` from it, the cover as well, and
  // the angle at the moved crease is no longer the truth's.
  const CadCase c = case_named("box-edge");
  const auto cut = cut_case(c);
  ASSERT_TRUE(cut);
  Mesh pushed = c.closed;
  const double push = 0.05;
  const Point inward = Point(-1.0, 0.0, -1.0).normalized();
  std::size_t moved = 0;
  for (const auto v : cut->holes.front().inner_vertices) {
    const Point p = pushed.point(v);
    if (std::abs(p[0] - 1.0) < 1e-12 && std::abs(p[2] - 1.0) < 1e-12) {
      pushed.set_point(v, p + inward * push);
      ++moved;
    }
  }
  ASSERT_GE(moved, 3u);
  const quality::Truth truth(c.closed);
  const auto q =
      measure_feature_fill(c.closed, truth, cut->holes.front(), pushed, truth_patch(*cut), false);
  const double diagonal = truth.diagonal();
  EXPECT_GT(q.crease_mean, 0.1 * push / diagonal);
  EXPECT_LE(q.crease_max, push / diagonal + 1e-12);
  EXPECT_LE(q.cover_max, push / diagonal + 1e-12);
  EXPECT_GT(q.cover_mean, 0.0);
  EXPECT_LT(q.crease_dihedral, 89.0);
  EXPECT_NEAR(q.truth_dihedral, 90.0, 1e-9);
}

}  // namespace
}  // namespace holefill::features
