// Self-intersections: a hole whose every patch must cross the mesh is left open with the reason
// (or, when intersections are allowed, filled and reported for its hole); where there is room for a
// valid patch, the fill makes none, and a stage that would make one is undone.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "exact_intersections.h"
#include "fill_guarantees.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "robust_test_util.h"
#include "test_meshes.h"

namespace holefill::testing {
namespace {

// Adds a closed tetrahedron with corners at the given points.
void add_tetrahedron(Mesh& mesh, const std::array<Point, 4>& p) {
  VertexHandle v[4];
  for (int i = 0; i < 4; ++i) v[i] = mesh.add_vertex(p[i]);
  // Orient outwards whatever the corners' order.
  const bool outward = OpenMesh::dot(OpenMesh::cross(p[1] - p[0], p[2] - p[0]), p[3] - p[0]) < 0.0;
  const int a = outward ? 1 : 2, b = outward ? 2 : 1;
  mesh.add_face(v[0], v[a], v[b]);
  mesh.add_face(v[0], v[3], v[a]);
  mesh.add_face(v[0], v[b], v[3]);
  mesh.add_face(v[a], v[3], v[b]);
}

// A patch made of the given faces of `mesh`.
Patch patch_of(const std::vector<FaceHandle>& faces) {
  Patch patch;
  patch.faces = faces;
  patch.stage = Stage::Triangulated;
  return patch;
}

// The base triangle (0,0,0) (2,0,0) (0,2,0) and one other; the other is the patch.
std::size_t intersections_with_base(const std::array<Point, 3>& other, bool share_corner = false) {
  Mesh mesh;
  const auto a = mesh.add_vertex({0, 0, 0}), b = mesh.add_vertex({2, 0, 0}),
             c = mesh.add_vertex({0, 2, 0});
  mesh.add_face(a, b, c);
  VertexHandle v[3];
  for (int i = 0; i < 3; ++i) {
    v[i] = share_corner && other[i] == Point(0, 0, 0) ? a : mesh.add_vertex(other[i]);
  }
  return count_patch_intersections(mesh, patch_of({mesh.add_face(v[0], v[1], v[2])}));
}

TEST(PatchIntersections, CountsCrossingsButNotTouching) {
  // Through the base's interior.
  EXPECT_EQ(intersections_with_base({Point(0.5, 0.5, -1), Point(0.5, 0.5, 1), Point(-1, 3, 0)}),
            1u);
  // Standing on the base's side: touches it along a segment.
  EXPECT_EQ(intersections_with_base({Point(0.5, 0, 0), Point(1, -1, 0.5), Point(1.5, 0, 0)}), 0u);
  // A corner resting on the base's interior: the interiors meet at that point.
  EXPECT_EQ(intersections_with_base({Point(0.5, 0.5, 0), Point(1, 1, 1), Point(0, 1, 1)}), 1u);
  // Sharing the base's corner and leaning away from it.
  EXPECT_EQ(intersections_with_base({Point(0, 0, 0), Point(-1, 0, 1), Point(-1, 1, 1)}, true), 0u);
  // Sharing the corner and folded down into the base's plane, over it.
  EXPECT_EQ(intersections_with_base({Point(0, 0, 0), Point(1, 0.2, 0), Point(0.2, 1, 0)}, true),
            1u);
  // In the base's plane beside it, sharing the corner.
  EXPECT_EQ(intersections_with_base({Point(0, 0, 0), Point(-1, -0.2, 0), Point(-0.2, -1, 0)}, true),
            0u);
  // Lying inside the base, in its plane.
  EXPECT_EQ(intersections_with_base({Point(0.2, 0.2, 0), Point(0.2, 0.8, 0), Point(0.8, 0.2, 0)}),
            1u);
  // Parallel to it, just above.
  EXPECT_EQ(intersections_with_base(
                {Point(0.2, 0.2, 1e-6), Point(0.8, 0.2, 1e-6), Point(0.2, 0.8, 1e-6)}),
            0u);
}

// A bumpy terrain with a round hole in the middle.
Mesh terrain_with_hole() {
  return without_faces(
      make_grid(16, [](double x, double y) { return 0.05 * std::sin(3 * x) * std::cos(2 * y); }),
      [](const Point& c) { return std::hypot(c[0] - 0.5, c[1] - 0.5) < 0.25; });
}

// The terrain's hole with a pin standing through its middle: any patch across the hole must
// cross the pin.
Mesh terrain_with_pinned_hole() {
  Mesh mesh = terrain_with_hole();
  add_tetrahedron(mesh, {Point(0.5, 0.5, -0.5), Point(0.52, 0.5, 0.5), Point(0.48, 0.52, 0.5),
                         Point(0.48, 0.48, 0.5)});
  return mesh;
}

TEST(PatchIntersections, AHoleEveryPatchOfWhichCutsTheMeshIsLeftOpenWithTheReason) {
  const Mesh before = terrain_with_pinned_hole();
  const auto holes = find_holes(before);
  ASSERT_EQ(holes.size(), 2u);
  Mesh mesh = before;
  HoleSelection inner;
  inner.hole_ids = {1};
  const auto fills = fill_holes(mesh, holes, {}, inner);
  ASSERT_EQ(fills.size(), 1u);
  EXPECT_TRUE(fills[0].failed());
  EXPECT_EQ(fills[0].failure.kind, FailureKind::IntersectsMesh) << fills[0].failure;
  EXPECT_GT(fills[0].refused_intersections, 0u);
  EXPECT_EQ(fills[0].self_intersections, 0u);
  EXPECT_TRUE(fills[0].patch.faces.empty());
  // Nothing was added: the same elements, positions and loops as before.
  EXPECT_EQ(mesh.n_faces(), before.n_faces());
  EXPECT_EQ(mesh.n_vertices(), before.n_vertices());
  EXPECT_EQ(find_holes(mesh).size(), 2u);
  EXPECT_EQ(check_fill_guarantees(before, holes, mesh, fills), "");
}

TEST(PatchIntersections, AllowingIntersectionsKeepsTheBestPatchAndReportsIt) {
  const Mesh before = terrain_with_pinned_hole();
  const auto holes = find_holes(before);
  Mesh mesh = before;
  FillOptions options;
  options.allow_intersections = true;
  const auto fills = fill_holes(mesh, holes, options, HoleSelection{{1}, 0});
  ASSERT_EQ(fills.size(), 1u);
  EXPECT_FALSE(fills[0].failed()) << fills[0].failure;
  EXPECT_GT(fills[0].self_intersections, 0u);
  EXPECT_EQ(fills[0].self_intersections, count_patch_intersections(mesh, fills[0].patch));
  EXPECT_GT(exact_patch_intersections(mesh, fills[0].patch.faces), 0u);
  EXPECT_EQ(check_fill_guarantees(before, holes, mesh, fills), "");
}

TEST(PatchIntersections, TheCliLeavesTheHoleOpenAndExitsWithOneUnlessAllowed) {
  // Per process: two test runs on one machine must not share it.
  const auto dir = std::filesystem::temp_directory_path() /
                   ("holefill_robust_cli_intersections_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  save_mesh(terrain_with_pinned_hole(), dir / "pin.obj");
  const std::vector<std::string> fill = {
      "fill",     (dir / "pin.obj").string(),    "-o", (dir / "out.obj").string(), "--holes", "1",
      "--report", (dir / "report.json").string()};
  const CliRun refused = run_cli(fill);
  EXPECT_EQ(refused.code, cli::kSomeHolesNotFilled) << refused.err;
  EXPECT_NE(refused.err.find("hole 1 not filled: every patch tried intersects the mesh"),
            std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("left open; --allow-intersections keeps it"), std::string::npos)
      << refused.err;
  EXPECT_EQ(load_mesh(dir / "out.obj").n_faces(), load_mesh(dir / "pin.obj").n_faces());
  const std::string refused_json = read_file(dir / "report.json");
  EXPECT_NE(refused_json.find("\"refused_intersections\": "), std::string::npos) << refused_json;
  EXPECT_NE(refused_json.find("\"filled\": false"), std::string::npos) << refused_json;
  EXPECT_NE(refused_json.find("\"failure_kind\": \"intersects-mesh\""), std::string::npos)
      << refused_json;

  std::vector<std::string> allowed = fill;
  allowed.push_back("--allow-intersections");
  const CliRun run = run_cli(allowed);
  EXPECT_EQ(run.code, cli::kPatchesIntersect) << run.err;
  EXPECT_NE(run.err.find("hole 1: the patch intersects the mesh"), std::string::npos) << run.err;
  const std::string json = read_file(dir / "report.json");
  EXPECT_NE(json.find("\"self_intersections\": "), std::string::npos);
  EXPECT_EQ(json.find("\"self_intersections\": 0"), std::string::npos) << json;
  // The avoidance tried and could not help: the pin crosses every patch.
  EXPECT_NE(json.find("\"intersection_avoidance\": {"), std::string::npos) << json;
  EXPECT_NE(json.find("\"changed\": false"), std::string::npos) << json;
  std::filesystem::remove_all(dir);
}

TEST(PatchIntersections, NoneWhereThereIsRoomForAValidPatch) {
  for (const char* asset : {"bunny.obj", "sphere.obj", "heart.obj", "torus.obj"}) {
    const Mesh before = load_mesh(std::filesystem::path(HOLEFILL_ASSETS_DIR) / asset);
    const auto holes = find_holes(before);
    for (const auto method : {SmoothMethod::Umbrella, SmoothMethod::Fair}) {
      Mesh mesh = before;
      FillOptions options;
      options.smooth.method = method;
      const auto fills = fill_holes(mesh, holes, options);
      for (const auto& fill : fills) {
        EXPECT_FALSE(fill.failed()) << asset << ": " << fill.failure;
        EXPECT_EQ(fill.self_intersections, 0u) << asset << " hole " << fill.hole_id;
      }
      EXPECT_EQ(check_fill_guarantees(before, holes, mesh, fills), "") << asset;
    }
  }
}

TEST(PatchIntersections, SmoothingThatWouldCrossTheMeshIsUndone) {
  // A sphere without its top cap, and a small closed body inside it just under where the cap
  // was: the flat triangulated and refined patch passes below the body, but fairing bulges the
  // patch up along the sphere, through it.
  Mesh before = without_faces(make_icosphere(3), [](const Point& c) { return c[2] > 0.7; });
  add_tetrahedron(before, {Point(0, 0, 0.8), Point(0.05, 0, 0.99), Point(-0.03, 0.04, 0.99),
                           Point(-0.03, -0.04, 0.99)});
  const auto holes = find_holes(before);
  ASSERT_EQ(holes.size(), 1u);
  FillOptions options;
  options.smooth.method = SmoothMethod::Fair;
  Mesh unguarded = before;
  options.last_stage = Stage::Refined;
  HoleFill refined = fill_hole(unguarded, holes[0], options);
  ASSERT_EQ(refined.self_intersections, 0u);
  // Fairing on its own would cross the body.
  ASSERT_TRUE(fair_patch(unguarded, refined.patch, options.smooth.fair).solved);
  ASSERT_GT(count_patch_intersections(unguarded, refined.patch), 0u);

  Mesh mesh = before;
  options.last_stage = Stage::Smoothed;
  const auto fills = fill_holes(mesh, holes, options);
  ASSERT_EQ(fills.size(), 1u);
  EXPECT_EQ(fills[0].stage(), Stage::Smoothed);
  EXPECT_EQ(fills[0].self_intersections, 0u);
  EXPECT_NE(fills[0].smoothing_note.find("smoothing undone: it made the patch intersect the mesh"),
            std::string::npos)
      << fills[0].smoothing_note;
  EXPECT_EQ(count_patch_intersections(mesh, fills[0].patch), 0u);
  EXPECT_EQ(check_fill_guarantees(before, holes, mesh, fills), "");
  // The undo deleted the smoothed patch with status flags requested for it, and released them.
  EXPECT_FALSE(mesh.has_vertex_status() || mesh.has_edge_status() || mesh.has_halfedge_status() ||
               mesh.has_face_status());
}

// Where along the line p + t n the patch's surface is (the smallest |t|); nothing if it misses.
std::optional<double> patch_crossing(const Mesh& mesh, const Patch& patch, const Point& p,
                                     const Point& n) {
  std::optional<double> nearest;
  for (const auto f : patch.faces) {
    auto fv = mesh.cfv_iter(f);
    const Point& a = mesh.point(*fv);
    const Point& b = mesh.point(*++fv);
    const Point& c = mesh.point(*++fv);
    const Point normal = OpenMesh::cross(b - a, c - a);
    const double along = OpenMesh::dot(normal, n);
    if (std::abs(along) < 1e-12 * normal.norm()) continue;
    const double t = OpenMesh::dot(normal, a - p) / along;
    const Point x = p + t * n;
    const bool inside = OpenMesh::dot(OpenMesh::cross(b - a, x - a), normal) >= 0.0 &&
                        OpenMesh::dot(OpenMesh::cross(c - b, x - b), normal) >= 0.0 &&
                        OpenMesh::dot(OpenMesh::cross(a - c, x - c), normal) >= 0.0;
    if (inside && (!nearest || std::abs(t) < std::abs(*nearest))) nearest = t;
  }
  return nearest;
}

TEST(PatchIntersections, RemeshingThatWouldCrossTheMeshIsUndoneAndTheRefinementKept) {
  // A flip of the remeshing pass puts the surface on a quad's other diagonal. A thin body
  // standing on such a new edge, reaching toward but not to where the refined patch's surface
  // is, is crossed by the remeshed patch alone; the stage then keeps the refinement without the
  // remeshing. The edge is found from the remeshed patch itself.
  const Mesh open = without_faces(make_icosphere(3), [](const Point& c) {
    return c[2] > 0.5 + 0.1 * std::sin(5.0 * std::atan2(c[1], c[0]));
  });
  const auto holes = find_holes(open);
  ASSERT_EQ(holes.size(), 1u);
  FillOptions plain;
  plain.last_stage = Stage::Refined;
  FillOptions remeshing = plain;
  remeshing.refine.remesh = true;
  Mesh refined = open, remeshed = open;
  const HoleFill refined_fill = fill_hole(refined, holes[0], plain);
  const HoleFill remeshed_fill = fill_hole(remeshed, holes[0], remeshing);
  ASSERT_GT(remeshed_fill.refinement.remeshing.flips, 0u);

  for (const auto e : remeshed.edges()) {
    const auto h = remeshed.halfedge_handle(e, 0);
    const VertexHandle c = remeshed.from_vertex_handle(h), d = remeshed.to_vertex_handle(h);
    if (remeshed.is_boundary(e) || refined.find_halfedge(c, d).is_valid()) continue;
    if (std::find(remeshed_fill.patch.faces.begin(), remeshed_fill.patch.faces.end(),
                  remeshed.face_handle(h)) == remeshed_fill.patch.faces.end()) {
      continue;
    }
    const Point middle = 0.5 * (remeshed.point(c) + remeshed.point(d));
    const Point normal = (remeshed.calc_face_normal(remeshed.face_handle(h)) +
                          remeshed.calc_face_normal(remeshed.opposite_face_handle(h)))
                             .normalized();
    const auto t = patch_crossing(refined, refined_fill.patch, middle, normal);
    if (!t || std::abs(*t) < 1e-4) continue;
    // A needle from a quarter of the gap behind the remeshed surface to half way to the refined.
    const Point tip = middle + 0.5 * *t * normal, foot = middle - 0.25 * *t * normal;
    const Point side = (remeshed.point(d) - remeshed.point(c)).normalized() * 0.05 * std::abs(*t);
    const Point other_side = OpenMesh::cross(normal, side);
    Mesh before = open;
    add_tetrahedron(
        before, {tip, foot + side, foot - 0.5 * side + other_side, foot - 0.5 * side - other_side});
    const auto loops = find_holes(before);
    ASSERT_EQ(loops.size(), 1u);
    Mesh unguarded = before;
    FillOptions triangulate_only = plain;
    triangulate_only.last_stage = Stage::Triangulated;
    const HoleFill triangulated = fill_hole(unguarded, loops[0], triangulate_only);
    // The needle must not change the triangulation the remeshed patch was found from.
    if (triangulated.self_intersections || triangulated.avoidance.changed) continue;
    Mesh refined_only = before;
    const HoleFill refined_again = fill_hole(refined_only, loops[0], plain);
    if (!refined_again.refinement_note.empty() || refined_again.self_intersections) continue;

    Mesh mesh = before;
    const auto fills = fill_holes(mesh, loops, remeshing);
    ASSERT_EQ(fills.size(), 1u);
    EXPECT_EQ(fills[0].refinement_note, "remeshing undone: it made the patch intersect the mesh");
    EXPECT_EQ(fills[0].self_intersections, 0u);
    EXPECT_EQ(fills[0].refinement.remeshing.flips, 0u);
    EXPECT_EQ(fills[0].stats.new_vertices, refined_again.stats.new_vertices);
    EXPECT_TRUE(original_part_unchanged(refined_only, mesh));  // the plain refinement, exactly
    EXPECT_EQ(check_fill_guarantees(before, loops, mesh, fills), "");
    return;
  }
  FAIL() << "no remeshed edge leaves room for a body between the two surfaces";
}

// An octahedron of a given size with its last face missing.
Mesh octahedron_without_a_face(double size) {
  Mesh mesh;
  const Point corners[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  VertexHandle v[6];
  for (int i = 0; i < 6; ++i) v[i] = mesh.add_vertex(size * corners[i]);
  const int faces[7][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                           {2, 0, 5}, {1, 2, 5}, {3, 1, 5}};
  for (const auto& f : faces) mesh.add_face(v[f[0]], v[f[1]], v[f[2]]);
  return mesh;
}

TEST(PatchIntersections, CoordinatesNearTheLargestDoublesAreSafe) {
  // At |x| = 8.5e153 squared lengths overflow; the intersection grid's margin became
  // infinite and a cell index NaN, and the grid was written out of bounds (SIGSEGV). At 1e200
  // and 1e-300 every triangle looked degenerate and the hole was refused. Any scale now gives
  // the unit octahedron's patch, scaled (the fill runs at a safe power-of-two scale).
  const Mesh unit = octahedron_without_a_face(1.0);
  const auto unit_holes = find_holes(unit);
  Mesh unit_filled = unit;
  const auto unit_fills = fill_holes(unit_filled, unit_holes, {});
  ASSERT_EQ(unit_fills.size(), 1u);
  ASSERT_FALSE(unit_fills[0].failed());
  for (const double size : {8.5e153, 1e200, 1e300, 1e-300}) {
    const Mesh before = octahedron_without_a_face(size);
    const auto holes = find_holes(before);
    ASSERT_EQ(holes.size(), 1u);
    Mesh mesh = before;
    const auto fills = fill_holes(mesh, holes, {});
    ASSERT_EQ(fills.size(), 1u);
    EXPECT_FALSE(fills[0].failed()) << size << ": " << fills[0].failure;
    EXPECT_EQ(fills[0].self_intersections, 0u) << size;
    EXPECT_TRUE(original_part_unchanged(before, mesh)) << size;
    EXPECT_TRUE(is_oriented_manifold(mesh)) << size;
    EXPECT_TRUE(find_holes(mesh).empty()) << size;
    ASSERT_EQ(mesh.n_vertices(), unit_filled.n_vertices()) << size;
    ASSERT_EQ(mesh.n_faces(), unit_filled.n_faces()) << size;
    for (const auto f : mesh.faces()) {
      auto a = mesh.cfv_iter(f);
      auto b = unit_filled.cfv_iter(FaceHandle(f.idx()));
      for (int c = 0; c < 3; ++c, ++a, ++b) EXPECT_EQ(a->idx(), b->idx()) << size;
    }
    for (const auto v : mesh.vertices()) {
      const Point expected = unit_filled.point(v) * size;
      for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(mesh.point(v)[axis] / size, expected[axis] / size, 1e-12) << size;
      }
    }
  }
}

}  // namespace
}  // namespace holefill::testing
