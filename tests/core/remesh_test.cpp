// The remeshing pass of the refine stage: it makes most new vertices regular, keeps the mesh a
// manifold without degenerate triangles or duplicate edges, moves nothing but the patch's new
// vertices, keeps a flat patch flat, and changes nothing at all when it is off.
#include "holefill/remesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "geometry.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/triangulate.h"
#include "test_meshes.h"

namespace holefill {
namespace {

using testing::is_oriented_manifold;
using testing::make_grid;
using testing::make_icosphere;
using testing::original_part_unchanged;
using testing::without_faces;

// A sphere with a wavy cap cut out: a hole of about 40 edges whose refinement adds ~100 vertices.
Mesh sphere_with_cap_hole() {
  return without_faces(make_icosphere(4), [](const Point& c) {
    return c[2] > 0.6 + 0.08 * std::sin(5.0 * std::atan2(c[1], c[0]));
  });
}

// A flat square with a round hole in its middle.
Mesh plane_with_hole() {
  return without_faces(make_grid(30, [](double, double) { return 0.0; }), [](const Point& c) {
    return std::hypot(c[0] - 0.5, c[1] - 0.5) < 0.3 + 0.05 * std::sin(6.0 * c[0]);
  });
}

// The inner hole of a mesh (for the plane: not the outer border, which has more edges).
const Hole& innermost(const std::vector<Hole>& holes) { return holes.back(); }

HoleFill refine_only(Mesh& mesh, const Hole& hole, bool remesh) {
  FillOptions options;
  options.last_stage = Stage::Refined;
  options.refine.remesh = remesh;
  return fill_hole(mesh, hole, options);
}

double valence6_share(const Mesh& mesh, const Patch& patch) {
  std::size_t regular = 0;
  for (const auto v : patch.new_vertices) regular += mesh.valence(v) == 6;
  return static_cast<double>(regular) / static_cast<double>(patch.new_vertices.size());
}

// Sum over the patch's vertices (boundary included) of the squared deviation from valence 6.
long squared_deviation_from_6(const Mesh& mesh, const Patch& patch) {
  long total = 0;
  auto add = [&](VertexHandle v) {
    const long off = static_cast<long>(mesh.valence(v)) - 6;
    total += off * off;
  };
  for (const auto v : patch.new_vertices) add(v);
  for (const auto v : patch.boundary) add(v);
  return total;
}

bool has_duplicate_edge(const Mesh& mesh) {
  std::set<std::pair<int, int>> seen;
  for (const auto e : mesh.edges()) {
    const auto h = mesh.halfedge_handle(e, 0);
    const int a = mesh.from_vertex_handle(h).idx(), b = mesh.to_vertex_handle(h).idx();
    if (!seen.insert({std::min(a, b), std::max(a, b)}).second) return true;
  }
  return false;
}

std::size_t degenerate_faces(const Mesh& mesh, const Patch& patch) {
  std::size_t count = 0;
  for (const auto f : patch.faces) {
    auto fv = mesh.cfv_iter(f);
    const Point& a = mesh.point(*fv);
    const Point& b = mesh.point(*++fv);
    const Point& c = mesh.point(*++fv);
    count += geometry::measure_triangle(a, b, c, false).degenerate;
  }
  return count;
}

TEST(Remesh, MakesMostNewVerticesOfASphereCapRegular) {
  const Mesh before = sphere_with_cap_hole();
  const auto holes = find_holes(before);
  ASSERT_EQ(holes.size(), 1u);
  Mesh plain = before, remeshed = before;
  const HoleFill without = refine_only(plain, holes[0], false);
  const HoleFill with = refine_only(remeshed, holes[0], true);
  ASSERT_FALSE(with.failed()) << with.failure;
  EXPECT_TRUE(with.refinement_note.empty()) << with.refinement_note;
  ASSERT_GT(without.patch.new_vertices.size(), 50u);
  // The pass neither adds nor removes vertices or faces.
  EXPECT_EQ(with.patch.new_vertices.size(), without.patch.new_vertices.size());
  EXPECT_EQ(with.patch.faces.size(), without.patch.faces.size());
  EXPECT_GT(with.refinement.remeshing.flips, 0u);
  EXPECT_GT(with.refinement.remeshing.moves, 0u);
  const double share_without = valence6_share(plain, without.patch);
  const double share_with = valence6_share(remeshed, with.patch);
  EXPECT_LT(share_without, 0.6);
  EXPECT_GT(share_with, 0.65);
  EXPECT_GT(share_with, share_without + 0.15);
  EXPECT_LT(squared_deviation_from_6(remeshed, with.patch),
            squared_deviation_from_6(plain, without.patch));
}

TEST(Remesh, NeverChangesTheBoundaryOrAnythingOutsideThePatch) {
  const Mesh before = sphere_with_cap_hole();
  const auto holes = find_holes(before);
  Mesh mesh = before;
  HoleFill fill = refine_only(mesh, holes[0], false);
  const Mesh refined = mesh;
  const Patch refined_patch = fill.patch;
  const RemeshResult result = remesh_patch(mesh, fill.patch);
  ASSERT_GT(result.flips, 0u);

  EXPECT_TRUE(original_part_unchanged(before, mesh));
  ASSERT_EQ(mesh.n_vertices(), refined.n_vertices());
  ASSERT_EQ(mesh.n_faces(), refined.n_faces());
  const std::set<int> moving = [&] {
    std::set<int> ids;
    for (const auto v : fill.patch.new_vertices) ids.insert(v.idx());
    return ids;
  }();
  for (const auto v : mesh.vertices()) {
    if (!moving.count(v.idx())) {
      EXPECT_EQ(mesh.point(v), refined.point(v)) << v.idx();
    }
  }
  // The same faces make the patch, and the hole's loop is still its border.
  EXPECT_EQ(fill.patch.faces, refined_patch.faces);
  EXPECT_EQ(fill.patch.new_vertices, refined_patch.new_vertices);
  EXPECT_EQ(fill.patch.boundary, refined_patch.boundary);
  const std::set<int> patch_faces = [&] {
    std::set<int> ids;
    for (const auto f : fill.patch.faces) ids.insert(f.idx());
    return ids;
  }();
  const auto& loop = fill.patch.boundary;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const auto h = mesh.find_halfedge(loop[i], loop[(i + 1) % loop.size()]);
    ASSERT_TRUE(h.is_valid());
    const auto inside = mesh.face_handle(h), outside = mesh.opposite_face_handle(h);
    EXPECT_NE(patch_faces.count(inside.idx()), patch_faces.count(outside.idx()));
  }
}

double smallest_angle(const Mesh& mesh, const Patch& patch) {
  return patch_stats(mesh, patch).min_angle_deg;
}

TEST(Remesh, MakesNoSliverThatRefinementDidNotHave) {
  for (const bool flat : {false, true}) {
    const Mesh before = flat ? plane_with_hole() : sphere_with_cap_hole();
    const auto holes = find_holes(before);
    const Hole& hole = innermost(holes);
    Mesh plain = before, remeshed = before;
    const HoleFill without = refine_only(plain, hole, false);
    const HoleFill with = refine_only(remeshed, hole, true);
    EXPECT_GE(smallest_angle(remeshed, with.patch),
              std::min(smallest_angle(plain, without.patch), 20.0));
  }
}

TEST(Remesh, KeepsAManifoldWithoutDegenerateTrianglesOrDuplicateEdges) {
  for (const bool flat : {false, true}) {
    const Mesh before = flat ? plane_with_hole() : sphere_with_cap_hole();
    Mesh mesh = before;
    const HoleFill fill = refine_only(mesh, innermost(find_holes(before)), true);
    ASSERT_FALSE(fill.failed()) << fill.failure;
    EXPECT_GT(fill.refinement.remeshing.flips, 0u);
    EXPECT_TRUE(is_oriented_manifold(mesh));
    EXPECT_FALSE(has_duplicate_edge(mesh));
    EXPECT_EQ(degenerate_faces(mesh, fill.patch), 0u);
    EXPECT_EQ(count_patch_intersections(mesh, fill.patch), 0u);
    EXPECT_EQ(find_holes(mesh).size(), find_holes(before).size() - 1);
  }
}

TEST(Remesh, KeepsAFlatPatchInItsPlaneAndFacingUp) {
  const Mesh before = plane_with_hole();
  Mesh mesh = before;
  const HoleFill fill = refine_only(mesh, innermost(find_holes(before)), true);
  ASSERT_FALSE(fill.failed());
  ASSERT_GT(fill.refinement.remeshing.moves, 0u);
  for (const auto v : fill.patch.new_vertices) EXPECT_NEAR(mesh.point(v)[2], 0.0, 1e-12);
  for (const auto f : fill.patch.faces) EXPECT_GT(mesh.calc_face_normal(f)[2], 0.99);
  EXPECT_GT(valence6_share(mesh, fill.patch), 0.65);
}

TEST(Remesh, OffGivesExactlyTheOutputWithoutThePass) {
  const Mesh before = sphere_with_cap_hole();
  const auto holes = find_holes(before);
  FillOptions off;
  FillOptions off_with_other_settings = off;
  off_with_other_settings.refine.remeshing.iterations = 50;
  off_with_other_settings.refine.remeshing.max_flip_dihedral_deg = 90.0;
  FillOptions on = off;
  on.refine.remesh = true;
  Mesh a = before, b = before, c = before;
  fill_holes(a, holes, off);
  const auto fills = fill_holes(b, holes, off_with_other_settings);
  fill_holes(c, holes, on);
  EXPECT_EQ(fills[0].refinement.remeshing.flips, 0u);
  EXPECT_EQ(fills[0].refinement.remeshing.moves, 0u);
  ASSERT_EQ(a.n_vertices(), b.n_vertices());
  ASSERT_EQ(a.n_faces(), b.n_faces());
  EXPECT_TRUE(original_part_unchanged(a, b));  // every vertex and face, the patch's included
  EXPECT_FALSE(original_part_unchanged(a, c));
}

TEST(Remesh, LeavesAPatchWithoutNewVerticesAsTheTriangulationMadeIt) {
  const Mesh before = sphere_with_cap_hole();
  const auto holes = find_holes(before);
  Mesh mesh = before;
  FillOptions options;
  options.last_stage = Stage::Triangulated;
  HoleFill fill = fill_hole(mesh, holes[0], options);
  const Mesh triangulated = mesh;
  const RemeshResult result = remesh_patch(mesh, fill.patch);
  EXPECT_EQ(result.flips, 0u);
  EXPECT_TRUE(original_part_unchanged(triangulated, mesh));
}

TEST(Remesh, TargetsValence6InsideAndTheAngleShareOnTheBoundary) {
  const Mesh before = sphere_with_cap_hole();
  Mesh mesh = before;
  const HoleFill fill = refine_only(mesh, find_holes(before)[0], false);
  for (const auto v : fill.patch.new_vertices) {
    EXPECT_EQ(target_valence(mesh, fill.patch, v), 6);
  }
  // Around the icosphere's regular vertices the cut leaves a fan of about 3 triangles on each
  // side: a target of the full 6 give or take one where the cut is lopsided.
  for (const auto v : fill.patch.boundary) {
    const int target = target_valence(mesh, fill.patch, v);
    EXPECT_GE(target, 5);
    EXPECT_LE(target, 7);
  }
}

}  // namespace
}  // namespace holefill
