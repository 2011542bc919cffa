// The room fill_holes reserves for its patches (patch_room.h): the triangulation's counts exactly,
// the refined patch's within a factor of two, and no copy of the arrays when a fill adds little.
#include "patch_room.h"

#include <gtest/gtest.h>

#include "hole_triangulation.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "test_meshes.h"

namespace holefill {
namespace {

using namespace holefill::testing;

// A sphere with a cap cut out: one hole, curved around.
Mesh capless_sphere() {
  return without_faces(make_icosphere(4), [](const Point& c) { return c[2] > 0.6; });
}

struct AddedCounts {
  std::size_t vertices, edges, faces;
};

// What filling the mesh's largest hole up to `last` adds, and the estimate for its plan.
std::pair<AddedCounts, detail::PatchRoom> filled_and_estimated(Stage last) {
  Mesh mesh = capless_sphere();
  const std::vector<Hole> holes = find_holes(mesh);
  EXPECT_EQ(holes.size(), 1u);
  const PlannedTriangulation plan = detail::plan_triangulation(mesh, holes[0], {});
  EXPECT_TRUE(plan.triangulation.has_value());
  const detail::PatchRoom room =
      detail::patch_room(mesh, holes[0], *plan.triangulation, last >= Stage::Refined);
  const std::size_t v = mesh.n_vertices(), e = mesh.n_edges(), f = mesh.n_faces();
  FillOptions options;
  options.last_stage = last;
  options.avoid_intersections = false;
  const HoleFill fill = fill_hole(mesh, holes[0], options);
  EXPECT_FALSE(fill.failed());
  return {{mesh.n_vertices() - v, mesh.n_edges() - e, mesh.n_faces() - f}, room};
}

TEST(PatchRoom, ATriangulationAddsItsFacesAndInnerEdgesExactly) {
  const auto [added, room] = filled_and_estimated(Stage::Triangulated);
  ASSERT_GT(added.faces, 20u);
  EXPECT_EQ(room.vertices, added.vertices);
  EXPECT_EQ(room.edges, added.edges);
  EXPECT_EQ(room.faces, added.faces);
}

TEST(PatchRoom, ARefinedPatchIsEstimatedWithinAFactorOfTwo) {
  const auto [added, room] = filled_and_estimated(Stage::Refined);
  ASSERT_GT(added.vertices, 20u);  // refinement added vertices, as the estimate must foresee
  for (const auto& [estimate, actual] :
       {std::pair{room.vertices, added.vertices}, std::pair{room.edges, added.edges},
        std::pair{room.faces, added.faces}}) {
    EXPECT_GE(2 * estimate, actual);
    EXPECT_LE(estimate, 2 * actual);
  }
}

std::size_t vertex_capacity(Mesh& mesh) {
  return mesh.property(mesh.points_pph()).data_vector().capacity();
}

TEST(PatchRoom, ReservesOnlyWhatGoesBeyondAnEighthMore) {
  Mesh mesh = make_icosphere(3);
  // The positions with no room beyond them, as a mesh read without the loader's eighth.
  mesh.property(mesh.points_pph()).data_vector().shrink_to_fit();
  const std::size_t capacity = vertex_capacity(mesh);
  ASSERT_EQ(capacity, mesh.n_vertices());
  const std::size_t eighth = mesh.n_vertices() / 8;
  detail::reserve_patch_room(mesh, {eighth, eighth, eighth});
  EXPECT_EQ(vertex_capacity(mesh), capacity);
  detail::reserve_patch_room(mesh, {eighth + 1, 0, 0});
  EXPECT_GE(vertex_capacity(mesh), mesh.n_vertices() + eighth + 1);
  EXPECT_GT(vertex_capacity(mesh), capacity);
  // An estimate of far more than the mesh holds reserves no more than twice its elements.
  mesh.property(mesh.points_pph()).data_vector().shrink_to_fit();
  detail::reserve_patch_room(mesh, {std::size_t{1} << 40, 0, 0});
  EXPECT_GE(vertex_capacity(mesh), 2 * mesh.n_vertices());
  EXPECT_LE(vertex_capacity(mesh), 2 * mesh.n_vertices() + mesh.n_vertices() / 4 + 64);
}

}  // namespace
}  // namespace holefill
