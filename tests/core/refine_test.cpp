// Step 2, refinement: the patch's density follows the surrounding mesh and tau, and the
// relaxation swaps edges by the opposite-angle rule.
#include "holefill/refine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <set>

#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "island_meshes.h"
#include "patch_face_set.h"
#include "refine_reference.h"
#include "test_meshes.h"

namespace holefill {
namespace {

using testing::first_difference;
using testing::sphere_with_two_holes;

TEST(Refine, PatchEdgesTrackTheSurroundingDensity) {
  const Mesh before = sphere_with_two_holes();
  const auto holes = find_holes(before);
  Mesh mesh = before;
  FillOptions options;
  options.last_stage = Stage::Refined;
  const HoleFill fill = fill_hole(mesh, holes[0], options);
  ASSERT_FALSE(fill.failed());
  double total = 0.0;
  int count = 0;
  for (const auto f : fill.patch.faces) {
    for (const auto e : mesh.fe_range(f)) {
      total += mesh.calc_edge_length(e);
      ++count;
    }
  }
  const double mean_patch_edge = total / count;
  const double surrounding = holes[0].mean_surrounding_edge_length;
  EXPECT_GT(mean_patch_edge, 0.7 * surrounding);
  EXPECT_LT(mean_patch_edge, 1.5 * surrounding);
}

TEST(Refine, LargerTauNeverGivesFewerVertices) {
  const Mesh before = sphere_with_two_holes();
  const auto holes = find_holes(before);
  std::size_t previous = 0;
  for (const double tau : {0.8, 1.0, 1.2, std::sqrt(2.0), 1.7, 2.0}) {
    Mesh mesh = before;
    FillOptions options;
    options.refine.tau = tau;
    options.last_stage = Stage::Refined;
    const HoleFill fill = fill_hole(mesh, holes[0], options);
    EXPECT_GE(fill.stats.new_vertices, previous) << "tau = " << tau;
    previous = fill.stats.new_vertices;
  }
  EXPECT_GT(previous, 0u);
}

// should_swap_edge on the edge a-b between triangles (a, c, b) and (b, d, a).
bool should_swap_quad_edge(const Point& a, const Point& b, const Point& c, const Point& d) {
  Mesh mesh;
  const VertexHandle va = mesh.add_vertex(a), vb = mesh.add_vertex(b), vc = mesh.add_vertex(c),
                     vd = mesh.add_vertex(d);
  mesh.add_face(va, vc, vb);
  mesh.add_face(vb, vd, va);
  return should_swap_edge(mesh, mesh.edge_handle(mesh.find_halfedge(va, vb)));
}

// The relaxation's swap test against its definition written with angles: swap when the angles
// opposite the edge sum to more than pi (by a 1e-9 margin) and the swap lowers that sum. Random
// quads folded out of plane, and quads close to co-circular, where a shortcut could misjudge.
TEST(Refine, SwapTestFollowsTheOppositeAngleRule) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int swaps = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    // a, b on the unit circle; c, d near it (exactly on it for some trials), lifted a little.
    const double near = trial % 4 == 0 ? 0.0 : (trial % 4 == 1 ? 1e-9 : 0.3) * unit(rng);
    auto on_circle = [&](double angle, double radius) {
      const double lift = trial % 2 ? 0.2 * unit(rng) : 0.0;
      return Point(radius * std::cos(angle), radius * std::sin(angle), lift);
    };
    const Point a = on_circle(std::numbers::pi * (0.5 + 0.4 * unit(rng)), 1.0);
    const Point b = on_circle(-std::numbers::pi * (0.5 + 0.4 * unit(rng)), 1.0);
    const Point c = on_circle(std::numbers::pi * (0.15 * unit(rng)), 1.0 + near);
    const Point d = on_circle(std::numbers::pi * (1.0 + 0.15 * unit(rng)), 1.0 - near);
    const bool expected = testing::swap_by_angles(a, b, c, d);
    EXPECT_EQ(should_swap_quad_edge(a, b, c, d), expected) << "trial " << trial;
    swaps += expected;
  }
  EXPECT_GT(swaps, 500);  // both outcomes are exercised
  EXPECT_LT(swaps, 3500);
}

// The same where the test decides by cotangents alone that an edge swaps: thin quads whose
// angle at c is 1e-5 to 0.03 radians (cotangents on both sides of the shortcut's bound of 100)
// and whose angle at d makes the pair exceed or miss pi by 1e-10 to 1e-2, some folded a little.
TEST(Refine, SwapTestFollowsTheOppositeAngleRuleOnThinQuads) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int swaps = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const double alpha = 1e-5 * std::pow(10.0, 3.5 * unit(rng));
    const double excess = (trial % 2 ? 1.0 : -1.0) * std::pow(10.0, -10.0 + 8.0 * unit(rng));
    const double beta = std::numbers::pi - alpha + excess;
    const double fold = trial % 3 ? 0.0 : 0.01 * unit(rng);
    const Point a(-1.0, 0.0, 0.0), b(1.0, 0.0, 0.0);
    const Point c(0.3 * unit(rng), 1.0 / std::tan(alpha / 2.0), fold);
    const Point d(0.0, -1.0 / std::tan(beta / 2.0), 0.0);
    const bool expected = testing::swap_by_angles(a, b, c, d);
    EXPECT_EQ(should_swap_quad_edge(a, b, c, d), expected) << "trial " << trial;
    swaps += expected;
  }
  EXPECT_GT(swaps, 1000);
  EXPECT_LT(swaps, 3000);
}

// The refinement's face set against std::set: faces from the patch, newer ones added, and (never
// while refining, but allowed) older ones.
TEST(Refine, PatchFaceSetAnswersLikeASet) {
  std::mt19937 rng(5);
  Patch patch;
  std::set<int> expected;
  for (int i = 0; i < 40; ++i) {
    const int id = 1000 + static_cast<int>(rng() % 200);
    patch.faces.push_back(FaceHandle(id));
    expected.insert(id);
  }
  detail::PatchFaceSet set(patch);
  for (int i = 0; i < 300; ++i) {
    const int id = static_cast<int>(rng() % 1600);
    EXPECT_EQ(set.insert(FaceHandle(id)), expected.insert(id).second) << id;
  }
  for (int id = -1; id < 1700; ++id) {
    EXPECT_EQ(set.contains(FaceHandle(id)), expected.count(id) > 0) << id;
  }
}

// Refinement on flat arrays against the OpenMesh refinement it replaced (refine_reference.h):
// every hole of `holed` triangulated, then each patch refined by both, patch after patch on one
// mesh (so that the earlier patches' faces are not the newest), must give the same mesh handle
// for handle, the same patch lists and the same counts.
struct Seen {
  std::size_t patches = 0, splits = 0, swaps = 0, vertex_cap_stops = 0, face_limit_stops = 0;
};

void expect_same_result(const RefineResult& result, const RefineResult& reference,
                        const std::string& where) {
  EXPECT_EQ(result.splits, reference.splits) << where;
  EXPECT_EQ(result.swaps, reference.swaps) << where;
  EXPECT_EQ(result.vertex_cap, reference.vertex_cap) << where;
  EXPECT_EQ(result.stopped_at_vertex_cap, reference.stopped_at_vertex_cap) << where;
  EXPECT_EQ(result.stopped_at_face_limit, reference.stopped_at_face_limit) << where;
  EXPECT_EQ(result.remeshing.flips, reference.remeshing.flips) << where;
  EXPECT_EQ(result.remeshing.moves, reference.remeshing.moves) << where;
}

// A mesh with every hole triangulated, and the patches.
struct Triangulated {
  Mesh mesh;
  std::vector<HoleFill> fills;
};

Triangulated triangulate_holes(const Mesh& holed) {
  Triangulated result{holed, {}};
  FillOptions triangulation;
  triangulation.last_stage = Stage::Triangulated;
  triangulation.allow_intersections = true;  // every patch, to refine (the ragged disk's border)
  result.fills = fill_holes(result.mesh, find_holes(holed), triangulation);
  return result;
}

Seen expect_refined_as_before(const Triangulated& triangulated, const RefineOptions& options,
                              const std::string& what) {
  const auto& [mesh, fills] = triangulated;
  Mesh expected = mesh, actual = mesh;
  Seen seen;
  for (const auto& fill : fills) {
    if (fill.failed()) continue;
    const std::string where = what + ", hole " + std::to_string(fill.hole_id);
    Patch want = fill.patch, got = fill.patch;
    RefineResult reference = testing::reference_refine_patch(expected, want, options);
    if (options.remesh) reference.remeshing = remesh_patch(expected, want, options.remeshing);
    const RefineResult result = refine_patch(actual, got, options);
    expect_same_result(result, reference, where);
    EXPECT_EQ(got.faces, want.faces) << where;
    EXPECT_EQ(got.new_vertices, want.new_vertices) << where;
    EXPECT_EQ(first_difference(expected, actual), "") << where;
    ++seen.patches;
    seen.splits += result.splits;
    seen.swaps += result.swaps;
    seen.vertex_cap_stops += result.stopped_at_vertex_cap;
    seen.face_limit_stops += result.stopped_at_face_limit;
  }
  return seen;
}

RefineOptions with_tau(double tau) {
  RefineOptions options;
  options.tau = tau;
  return options;
}

TEST(Refine, FlatArraysRefineTheAssetsAsOpenMeshDid) {
  Seen all;
  for (const char* asset :
       {"bunny.obj", "heart.obj", "sphere.obj", "torus.obj", "ragged_disk.obj"}) {
    const auto triangulated =
        triangulate_holes(load_mesh(std::string(HOLEFILL_ASSETS_DIR) + "/" + asset));
    for (const double tau : {1.0, std::sqrt(2.0), 2.0}) {
      const Seen seen = expect_refined_as_before(
          triangulated, with_tau(tau), std::string(asset) + " tau " + std::to_string(tau));
      all.patches += seen.patches;
      all.splits += seen.splits;
      all.swaps += seen.swaps;
    }
  }
  EXPECT_GT(all.patches, 20u);
  EXPECT_GT(all.splits, 5000u);
  EXPECT_GT(all.swaps, 1000u);
}

// A bumpy closed blob with a hole of wavy outline around a direction that each seed draws.
Mesh blob_with_wavy_hole(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Point axis = Point(unit(rng), unit(rng), unit(rng) + 2.0).normalized();
  const Point across = OpenMesh::cross(axis, Point(1, 0, 0)).normalized();
  const Point third = OpenMesh::cross(axis, across);
  const double reach = 0.5 + 0.3 * unit(rng), wave = 0.3 * unit(rng), phase = 3.0 * unit(rng);
  const int lobes = 2 + static_cast<int>(rng() % 5);
  const Mesh blob = testing::make_blob(4, [](const Point& d) {
    return 1.0 + 0.1 * std::sin(4.0 * d[0]) * std::cos(3.0 * d[1] + 1.0);
  });
  return testing::without_faces(blob, [&](const Point& c) {
    const Point d = c.normalized();
    const double azimuth = std::atan2(OpenMesh::dot(d, third), OpenMesh::dot(d, across));
    return std::acos(OpenMesh::dot(d, axis)) <
           reach * (1.0 + wave * std::sin(lobes * azimuth + phase));
  });
}

TEST(Refine, FlatArraysRefineGeneratedHolesAsOpenMeshDid) {
  Seen all;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const auto triangulated = triangulate_holes(blob_with_wavy_hole(seed));
    for (const double tau : {1.2, std::sqrt(2.0), 3.0}) {
      const Seen seen = expect_refined_as_before(
          triangulated, with_tau(tau),
          "wavy hole " + std::to_string(seed) + " tau " + std::to_string(tau));
      all.splits += seen.splits;
      all.swaps += seen.swaps;
    }
  }
  expect_refined_as_before(triangulate_holes(testing::grid_with_square_holes(13)), with_tau(6.0),
                           "square holes");
  expect_refined_as_before(triangulate_holes(sphere_with_two_holes()), with_tau(1.7), "sphere");
  const Mesh islands = testing::cut_around_islands(
      testing::make_blob(3, [](const Point&) { return 1.0; }), {Point(0, 0, 1), 0.9},
      {{Point(0, 0, 1), 0.25}, {Point(0.5, 0, 0.85).normalized(), 0.12}});
  const Seen seen = expect_refined_as_before(triangulate_holes(islands), with_tau(1.3), "islands");
  EXPECT_EQ(seen.patches, 1u);
  EXPECT_GT(all.splits, 2000u);
  EXPECT_GT(all.swaps, 500u);
}

// The vertex cap and the face limit stop the flat refinement where they stopped OpenMesh's.
TEST(Refine, FlatArraysStopWhereOpenMeshStopped) {
  const Mesh heart = load_mesh(std::string(HOLEFILL_ASSETS_DIR) + "/heart.obj");
  RefineOptions capped = with_tau(6.0);
  capped.max_density = 4.0;
  const Seen at_cap =
      expect_refined_as_before(triangulate_holes(heart), capped, "heart, vertex cap");
  EXPECT_GT(at_cap.vertex_cap_stops, 0u);
  RefineOptions limited = with_tau(2.0);
  const auto blob = triangulate_holes(blob_with_wavy_hole(3));
  // 350 and 351 are reached by splitting the last face of a round: the stop then comes at the
  // next round, after the relaxation.
  for (const std::size_t limit : {60, 151, 350, 351}) {
    limited.max_patch_faces = limit;
    const Seen at_limit =
        expect_refined_as_before(blob, limited, "face limit " + std::to_string(limit));
    EXPECT_EQ(at_limit.face_limit_stops, 1u);
  }
  std::size_t stops = 0;
  for (std::size_t limit = 2; limit < 300; limit += 9) {
    limited.max_patch_faces = limit;
    stops +=
        expect_refined_as_before(blob, limited, "limit " + std::to_string(limit)).face_limit_stops;
  }
  EXPECT_GT(stops, 30u);
  for (double density = 0.05; density < 3.0; density += 0.1) {
    capped.max_density = density;
    stops += expect_refined_as_before(blob, capped, "density " + std::to_string(density))
                 .vertex_cap_stops;
  }
  EXPECT_GT(stops, 55u);
}

// With remeshing after it, which reads the mesh that the flat refinement wrote.
TEST(Refine, FlatArraysThenRemeshingAsBefore) {
  RefineOptions options = with_tau(std::sqrt(2.0));
  options.remesh = true;
  const Seen seen =
      expect_refined_as_before(triangulate_holes(blob_with_wavy_hole(4)), options, "remeshed");
  EXPECT_GT(seen.splits, 100u);
}

// relax_patch_edges on filled patches whose new vertices were then moved at random, up to
// `roughness` in each direction (the blob's edges are about 0.055 long): the rougher, the more
// swaps, and the more often the edge a swap would make exists already.
std::size_t expect_relaxed_as_before(unsigned seed, double roughness) {
  Mesh expected = blob_with_wavy_hole(seed);
  FillOptions options;
  options.refine.tau = 1.2;
  const auto fills = fill_holes(expected, find_holes(expected), options);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> shift(-roughness, roughness);
  for (const auto& fill : fills) {
    for (const auto v : fill.patch.new_vertices) {
      expected.point(v) += Point(shift(rng), shift(rng), shift(rng));
    }
  }
  Mesh actual = expected;
  std::size_t swaps = 0;
  for (const auto& fill : fills) {
    const std::size_t reference = testing::reference_relax_patch_edges(expected, fill.patch);
    EXPECT_EQ(relax_patch_edges(actual, fill.patch), reference) << "seed " << seed;
    EXPECT_EQ(first_difference(expected, actual), "") << "seed " << seed;
    swaps += reference;
  }
  return swaps;
}

TEST(Refine, FlatRelaxationSwapsAsOpenMeshDid) {
  std::size_t swaps = 0;
  for (unsigned seed = 1; seed <= 8; ++seed) {
    for (const double roughness : {0.01, 0.04}) swaps += expect_relaxed_as_before(seed, roughness);
  }
  EXPECT_GT(swaps, 200u);
}

// A closed, spiky little mesh taken whole as a patch (an icosphere of `level` with each vertex
// at a random radius), relaxed and refined both ways; returns the reference's swaps.
std::size_t expect_spiky_mesh_as_before(unsigned seed, int level, double min_radius) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> radius(min_radius, 2.0 - min_radius);
  Mesh expected = testing::make_icosphere(level);
  for (const auto v : expected.vertices()) expected.point(v) *= radius(rng);
  Patch want;
  for (const auto f : expected.faces()) want.faces.push_back(f);
  Patch got = want;
  Mesh actual = expected;
  const std::size_t swaps = testing::reference_relax_patch_edges(expected, want);
  EXPECT_EQ(relax_patch_edges(actual, got), swaps) << "seed " << seed;
  EXPECT_EQ(first_difference(expected, actual), "") << "seed " << seed;
  RefineOptions options;
  options.max_patch_faces = 700;  // no boundary: every face is too coarse
  testing::reference_refine_patch(expected, want, options);
  refine_patch(actual, got, options);
  EXPECT_EQ(got.faces, want.faces) << "seed " << seed;
  EXPECT_EQ(first_difference(expected, actual), "") << "seed " << seed;
  return swaps;
}

// On such meshes many a swap would make an edge that exists already (which OpenMesh's is_flip_ok
// refuses), made by an earlier swap or not.
TEST(Refine, FlatArraysRefuseSwapsThatDoubleAnEdge) {
  std::size_t swaps = 0;
  for (unsigned seed = 0; seed < 100; ++seed) {
    swaps += expect_spiky_mesh_as_before(seed, 1 + seed % 2, 0.2);
  }
  EXPECT_GT(swaps, 100u);
  // Seeds found among 30,000 where a swap refused in one sweep is made in a later one, after a
  // swap elsewhere removed the edge in the way.
  for (const unsigned seed : {1725u, 5890u, 10594u, 13722u}) {
    expect_spiky_mesh_as_before(seed, static_cast<int>(seed % 3), 0.05);
  }
}

// Two triangles glued back to back: each edge's two faces have the same third corner, whose
// obtuse angle asks for a swap that would join that corner to itself.
TEST(Refine, FlatArraysRefuseSwapsOnAPillow) {
  Mesh expected;
  const VertexHandle a = expected.add_vertex(Point(0, 0, 0)),
                     b = expected.add_vertex(Point(2, 0, 0)),
                     c = expected.add_vertex(Point(1, 0.3, 0));
  expected.add_face(a, b, c);
  expected.add_face(b, a, c);
  Patch patch;
  for (const auto f : expected.faces()) patch.faces.push_back(f);
  EXPECT_TRUE(should_swap_edge(expected, expected.edge_handle(expected.find_halfedge(a, b))));
  Mesh actual = expected;
  EXPECT_EQ(testing::reference_relax_patch_edges(expected, patch), 0u);
  EXPECT_EQ(relax_patch_edges(actual, patch), 0u);
  EXPECT_EQ(first_difference(expected, actual), "");
}

// A patch that lists a face twice is refused before anything is added.
TEST(Refine, PatchListingAFaceTwiceIsRefused) {
  const auto triangulated = triangulate_holes(blob_with_wavy_hole(2));
  ASSERT_FALSE(triangulated.fills.empty());
  Mesh mesh = triangulated.mesh;
  Patch patch = triangulated.fills[0].patch;
  patch.faces.push_back(patch.faces.front());
  const std::size_t faces = mesh.n_faces(), vertices = mesh.n_vertices();
  EXPECT_THROW(refine_patch(mesh, patch), std::logic_error);
  EXPECT_THROW(relax_patch_edges(mesh, patch), std::logic_error);
  EXPECT_EQ(mesh.n_faces(), faces);
  EXPECT_EQ(mesh.n_vertices(), vertices);
}

}  // namespace
}  // namespace holefill
