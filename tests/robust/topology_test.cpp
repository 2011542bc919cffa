// Awkward topology. Each mesh is written as an OBJ file, loaded, and every hole
// filled; every fill must keep the guarantees of fill_guarantees.h, each hole is either filled or
// left exactly as it was with a reason, and the CLI's exit code says which happened.
#include <cmath>
#include <numbers>
#include <numeric>

#include "dirty_meshes.h"
#include "fill_guarantees.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/stats.h"
#include "robust_test_util.h"
#include "test_meshes.h"

namespace holefill::testing {
namespace {
namespace fs = std::filesystem;

struct Outcome {
  Mesh before;
  LoadReport report;
  std::vector<Hole> holes;
  Mesh after;
  std::vector<HoleFill> fills;
  CliRun cli;

  std::size_t filled() const {
    return static_cast<std::size_t>(
        std::count_if(fills.begin(), fills.end(), [](const HoleFill& f) { return !f.failed(); }));
  }
  std::size_t failed_with(FailureKind kind) const {
    return static_cast<std::size_t>(std::count_if(
        fills.begin(), fills.end(), [&](const HoleFill& f) { return f.failure.kind == kind; }));
  }
  std::string failures() const {
    std::string text;
    for (const auto& f : fills) {
      if (f.failed()) text += "hole " + std::to_string(f.hole_id) + ": " + f.failure.message + "\n";
    }
    return text;
  }
};

class Topology : public ScratchTest {
 protected:
  // Writes the soup as an OBJ file, loads it, fills the selected holes, checks the guarantees,
  // and runs `holefill fill` on the same file.
  Outcome fill_file(const Soup& soup, const FillOptions& options = {},
                    const HoleSelection& selection = {}, bool run_the_cli = true) const {
    const fs::path file = write("input.obj", obj_text(soup));
    Outcome o;
    o.before = load_mesh(file, &o.report);
    o.holes = find_holes(o.before);
    o.after = o.before;
    o.fills = fill_holes(o.after, o.holes, options, selection);
    EXPECT_EQ(check_fill_guarantees(o.before, o.holes, o.after, o.fills), "");
    if (run_the_cli) {
      std::vector<std::string> args{"fill", file.string(), "-o", path("out.obj")};
      if (options.last_stage == Stage::Triangulated) {
        args.insert(args.end(), {"--stage", "triangulate"});
      }
      for (std::size_t i = 0; i < selection.hole_ids.size(); ++i) {
        args.insert(args.end(), {"--holes", std::to_string(selection.hole_ids[i])});
      }
      o.cli = run_cli(args);
    }
    return o;
  }
};

// An icosphere as a file would list it.
Soup sphere(int levels, const Point& offset = Point(0, 0, 0)) {
  Soup soup = soup_of(make_icosphere(levels));
  for (auto& p : soup.points) p += offset;
  return soup;
}

Point centroid(const Soup& soup, const std::vector<int>& face) { return face_centroid(soup, face); }

Soup terrain(int n) { return terrain_soup(n); }

TEST_F(Topology, ANonManifoldEdgeKeepsItsThirdFaceApartAndTheRestIsFilled) {
  Soup soup = without(sphere(2), [](const Point& c) { return c[2] > 0.8; });
  // A fin: a third face on an edge that two faces of the sphere share.
  const auto& f = soup.faces[0];
  soup.points.push_back(centroid(soup, f) * 2.0);
  soup.faces.push_back({f[0], f[1], static_cast<int>(soup.points.size()) - 1});
  const Outcome o = fill_file(soup);
  EXPECT_EQ(o.report.faces_detached, 1u);
  ASSERT_EQ(o.holes.size(), 2u);  // the cap, and the fin's own back
  EXPECT_EQ(o.filled(), 1u) << o.failures();
  EXPECT_EQ(o.failed_with(FailureKind::BackOfLoneTriangle), 1u) << o.failures();
  // The CLI tells the fin's back from a hole and leaves it out: every hole is filled.
  EXPECT_EQ(o.cli.code, cli::kOk) << o.cli.err;
  EXPECT_NE(o.cli.err.find("non-manifold faces were kept on their own copies"), std::string::npos);
  EXPECT_NE(o.cli.err.find("loop 1 is not a hole but the rim of a lone triangle"),
            std::string::npos)
      << o.cli.err;
}

TEST_F(Topology, ClosedSurfacesTouchingAtAVertexAreSplitApart) {
  // Two tetrahedra that share one tip.
  const Soup soup{
      {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
      {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 5, 4}, {0, 4, 6}, {0, 6, 5}, {4, 5, 6}}};
  const Outcome o = fill_file(soup);
  EXPECT_EQ(o.report.vertices_split, 1u);
  EXPECT_EQ(o.report.faces_detached, 0u);
  EXPECT_EQ(o.before.n_vertices(), 8u);
  EXPECT_TRUE(o.holes.empty());
  EXPECT_EQ(o.cli.code, cli::kOk) << o.cli.err;
  EXPECT_NE(o.cli.err.find("1 vertices where closed surfaces touch were split"), std::string::npos);
}

TEST_F(Topology, ABowtieOfTwoFacesOfABipyramidIsFilledManifold) {
  // Two faces of a triangular bipyramid that share one equator vertex (vertex 0): the loop around
  // them passes twice through it.
  const Soup soup{{{-0.5, 0.866, 0}, {1, 0, 0}, {0, 0, 1}, {-0.5, -0.866, 0}, {0, 0, -1}},
                  {{1, 0, 2}, {3, 0, 4}}};
  const Outcome o = fill_file(soup);
  ASSERT_EQ(o.holes.size(), 1u);
  EXPECT_TRUE(o.holes[0].pinched);
  EXPECT_EQ(o.holes[0].repeated_vertices, 1u);
  // Filled with each pass a corner, the vertex becomes manifold.
  EXPECT_EQ(o.filled(), 1u) << o.failures();
  EXPECT_FALSE(o.before.is_manifold(VertexHandle(0)));
  EXPECT_TRUE(o.after.is_manifold(VertexHandle(0)));
  EXPECT_TRUE(find_holes(o.after).empty());
  EXPECT_EQ(o.cli.code, cli::kOk) << o.cli.err;
}

TEST_F(Topology, ABowtieOfTwoFlatTrianglesIsLeftOpenAndIsNoHoleForTheCli) {
  const Soup soup{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}},
                  {{0, 1, 2}, {0, 3, 4}}};
  const Outcome o = fill_file(soup);
  ASSERT_EQ(o.holes.size(), 1u);
  // Any patch over the loop lies on the triangles' backs (do no harm): left open as it was.
  ASSERT_EQ(o.fills.size(), 1u);
  EXPECT_TRUE(o.fills[0].failed());
  EXPECT_GT(o.fills[0].refused_intersections, 0u);
  EXPECT_EQ(o.after.n_faces(), 2u);
  // Both triangles lie in one plane: the CLI does not take their rim for a hole.
  EXPECT_EQ(o.cli.code, cli::kOk) << o.cli.err;
  EXPECT_NE(o.cli.err.find("not a hole but the rim of a lone triangle"), std::string::npos);
}

TEST_F(Topology, FlippedFacesAreTurnedToAgreeWithTheirNeighbours) {
  Soup soup = without(sphere(2), [](const Point& c) { return c[2] > 0.8; });
  std::size_t flipped = 0;
  for (std::size_t f = 0; f < soup.faces.size(); f += 7, ++flipped) {
    std::swap(soup.faces[f][1], soup.faces[f][2]);
  }
  const Outcome o = fill_file(soup);
  EXPECT_EQ(o.report.faces_flipped, flipped);
  EXPECT_EQ(o.report.faces_detached, 0u);
  ASSERT_EQ(o.holes.size(), 1u);
  EXPECT_EQ(o.filled(), 1u) << o.failures();
  for (const auto f : o.after.faces()) {
    Point c(0, 0, 0);
    for (const auto v : o.after.fv_range(f)) c += o.after.point(v);
    EXPECT_GT(OpenMesh::dot(o.after.calc_face_normal(f), c), 0.0) << "face " << f.idx();
  }
  EXPECT_EQ(o.cli.code, cli::kOk) << o.cli.err;
  EXPECT_NE(o.cli.err.find("faces were flipped"), std::string::npos);
}

TEST_F(Topology, AMoebiusStripLoadsWithItsConflictDetached) {
  Soup soup;
  const int segments = 24;
  for (int i = 0; i < segments; ++i) {
    const double t = 2.0 * std::numbers::pi * i / segments;
    for (const double s : {-0.3, 0.3}) {
      soup.points.emplace_back((1 + s * std::cos(t / 2)) * std::cos(t),
                               (1 + s * std::cos(t / 2)) * std::sin(t), s * std::sin(t / 2));
    }
  }
  for (int i = 0; i < segments; ++i) {
    const int a = 2 * i, b = 2 * i + 1;
    // The last quad joins the first one with a half twist.
    const int c = i + 1 < segments ? 2 * i + 2 : 1, d = i + 1 < segments ? 2 * i + 3 : 0;
    soup.faces.push_back({a, c, d});
    soup.faces.push_back({a, d, b});
  }
  const Outcome o = fill_file(soup);
  EXPECT_GE(o.report.faces_detached, 1u);
  EXPECT_LT(o.report.faces_detached, 3u);
  EXPECT_EQ(o.before.n_faces(), soup.faces.size());
  EXPECT_GE(o.cli.code, cli::kOk);
  EXPECT_NE(o.cli.code, cli::kBadInput);
  EXPECT_NE(o.cli.code, cli::kInternalError);
}

TEST_F(Topology, ZeroAreaFacesBesideAHoleAreKeptAndTheHoleFilledAroundThem) {
  Soup soup =
      without(terrain(12), [](const Point& c) { return std::hypot(c[0] - 0.5, c[1] - 0.5) < 0.2; });
  Mesh probe;
  for (const auto& p : soup.points) probe.add_vertex(p);
  for (const auto& f : soup.faces)
    probe.add_face(VertexHandle(f[0]), VertexHandle(f[1]), VertexHandle(f[2]));
  // Split three edges of the inner hole at their midpoints with a zero-area face each.
  const auto holes = find_holes(probe);
  ASSERT_EQ(holes.size(), 2u);
  const Hole& inner = holes[1];
  for (int e = 0; e < 3; ++e) {
    const int a = inner.vertices[2 * e].idx(), b = inner.vertices[2 * e + 1].idx();
    soup.points.push_back((soup.points[a] + soup.points[b]) * 0.5);
    soup.faces.push_back({a, b, static_cast<int>(soup.points.size()) - 1});
  }
  HoleSelection selection;
  selection.hole_ids = {1};
  const Outcome o = fill_file(soup, {}, selection);
  EXPECT_EQ(o.report.degenerate_faces_dropped, 0u);
  EXPECT_EQ(o.before.n_faces(), soup.faces.size());
  ASSERT_EQ(o.fills.size(), 1u);
  EXPECT_EQ(o.holes[1].size(), inner.size() + 3);
  EXPECT_FALSE(o.fills[0].failed()) << o.failures();
  EXPECT_EQ(o.fills[0].self_intersections, 0u);
  EXPECT_EQ(o.cli.code, cli::kOk) << o.cli.err;
}

TEST_F(Topology, IsolatedVerticesAreKeptAndCounted) {
  Soup soup = without(sphere(2), [](const Point& c) { return c[2] > 0.8; });
  for (int i = 0; i < 3; ++i) soup.points.emplace_back(5.0 + i, 0, 0);
  const Outcome o = fill_file(soup);
  // The cap's inner vertices are left unused too.
  const auto unused = static_cast<std::size_t>(
      std::count_if(o.before.vertices().begin(), o.before.vertices().end(),
                    [&](VertexHandle v) { return o.before.is_isolated(v); }));
  EXPECT_EQ(o.report.isolated_vertices, unused);
  EXPECT_GE(unused, 3u);
  EXPECT_EQ(o.filled(), 1u);
  EXPECT_EQ(o.cli.code, cli::kOk) << o.cli.err;
  EXPECT_EQ(load_mesh(path("out.obj")).n_vertices(), o.after.n_vertices());
}

TEST_F(Topology, EveryComponentGetsItsHolesFilled) {
  const auto cut = [](const Point& c) { return std::abs(c[2]) > 0.85; };
  const Soup soup = append(without(sphere(2), cut), without(sphere(2, Point(3, 0, 0)), cut));
  const Outcome o = fill_file(soup);
  EXPECT_EQ(o.holes.size(), 4u);
  EXPECT_EQ(o.filled(), 4u) << o.failures();
  EXPECT_TRUE(find_holes(o.after).empty());
  EXPECT_EQ(connected_components(o.after), 2u + (o.before.n_vertices() - [&] {
                                             std::size_t used = 0;
                                             for (const auto v : o.before.vertices())
                                               used += o.before.is_isolated(v) ? 0 : 1;
                                             return used;
                                           }()));
  EXPECT_EQ(o.cli.code, cli::kOk) << o.cli.err;
}

TEST_F(Topology, AClosedMeshHasNothingToFill) {
  const Outcome o = fill_file(sphere(2));
  EXPECT_TRUE(o.holes.empty());
  EXPECT_TRUE(o.fills.empty());
  EXPECT_EQ(o.cli.code, cli::kOk) << o.cli.err;
  EXPECT_NE(o.cli.out.find("filled 0 of 0 selected holes"), std::string::npos) << o.cli.out;
  EXPECT_TRUE(fs::exists(path("out.obj")));
}

TEST_F(Topology, ThreeEdgeHolesGetOneTriangleEach) {
  Soup soup = sphere(2);
  for (const int f : {100, 30, 5}) soup.faces.erase(soup.faces.begin() + f);
  const Outcome o = fill_file(soup);
  ASSERT_EQ(o.holes.size(), 3u);
  for (const auto& fill : o.fills) {
    EXPECT_EQ(fill.boundary_edges, 3u);
    EXPECT_FALSE(fill.failed()) << fill.failure;
    EXPECT_EQ(fill.patch.faces.size(), 1u);
    EXPECT_EQ(fill.self_intersections, 0u);
  }
  EXPECT_TRUE(find_holes(o.after).empty());
  EXPECT_EQ(o.cli.code, cli::kOk) << o.cli.err;
}

TEST_F(Topology, TwoHolesSharingAVertexAreBothFilled) {
  const int n = 10;
  const Soup grid = terrain(n);
  // Cells (3,3) and (4,4) touch at the vertex between them.
  auto in_cell = [n](const Point& c, int i, int j) {
    const double h = 1.0 / (n - 1);
    return c[0] > i * h && c[0] < (i + 1) * h && c[1] > j * h && c[1] < (j + 1) * h;
  };
  const Soup soup =
      without(grid, [&](const Point& c) { return in_cell(c, 3, 3) || in_cell(c, 4, 4); });
  const Outcome o = fill_file(soup, {}, HoleSelection{{1, 2}, 0});
  ASSERT_EQ(o.holes.size(), 3u);  // the border and the two cells
  EXPECT_TRUE(o.holes[1].pinched);
  EXPECT_TRUE(o.holes[2].pinched);
  EXPECT_EQ(o.filled(), 2u) << o.failures();
  const VertexHandle shared(4 * n + 4);
  EXPECT_FALSE(o.before.is_manifold(shared));
  EXPECT_TRUE(o.after.is_manifold(shared));
  EXPECT_EQ(find_holes(o.after).size(), 1u);
  EXPECT_EQ(o.cli.code, cli::kOk) << o.cli.err;
}

TEST_F(Topology, AHoleWhoseCornersAreAlreadyJoinedElsewhereIsFilledAcrossTheOtherDiagonal) {
  // A tetrahedron A B C D without faces A B C and A C D: a square hole whose diagonal B-D is an
  // edge of the two faces left. Any weight would pick it on this shape; the patch uses A-C.
  const Soup soup{{{0, 0, 0}, {1, 0, 0.2}, {1, 1, 0}, {0, 1, 0.2}},  // A B C D
                  {{0, 3, 1}, {1, 3, 2}}};
  for (const auto weight : {WeightKind::MaxMin, WeightKind::Liepa, WeightKind::Area}) {
    FillOptions options;
    options.triangulate.weight = weight;
    const Outcome o = fill_file(soup, options);
    ASSERT_EQ(o.fills.size(), 1u);
    EXPECT_FALSE(o.fills[0].failed()) << o.failures();
    EXPECT_TRUE(o.after.find_halfedge(VertexHandle(0), VertexHandle(2)).is_valid());
    EXPECT_TRUE(find_holes(o.after).empty());
  }
}

// A band between a ring of `inner` points (radius 1, raised) and a ring of as many points
// (radius 2): its inner rim is a hole of inner.size() edges.
Soup band(const std::vector<double>& inner_angles) {
  Soup soup;
  const int n = static_cast<int>(inner_angles.size());
  for (const double a : inner_angles) soup.points.emplace_back(std::cos(a), std::sin(a), 0.3);
  for (const double a : inner_angles) soup.points.emplace_back(2 * std::cos(a), 2 * std::sin(a), 0);
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    soup.faces.push_back({i, n + i, n + j});
    soup.faces.push_back({i, n + j, j});
  }
  return soup;
}

TEST_F(Topology, CollinearOrNearlyCoincidentBoundaryPointsGiveNoDegenerateTriangle) {
  // A rectangular hole in a terrain: many collinear boundary points.
  const Soup rectangle = without(terrain(14), [](const Point& c) {
    return c[0] > 0.2 && c[0] < 0.8 && c[1] > 0.4 && c[1] < 0.6;
  });
  Outcome o = fill_file(rectangle, {}, HoleSelection{{1}, 0});
  ASSERT_EQ(o.fills.size(), 1u);
  EXPECT_FALSE(o.fills[0].failed()) << o.failures();

  // Two boundary points 1e-7 apart (relative to a radius of 1).
  std::vector<double> angles;
  for (int i = 0; i < 24; ++i) angles.push_back(2 * std::numbers::pi * i / 24);
  angles.insert(angles.begin() + 1, 1e-7);
  o = fill_file(band(angles), {}, HoleSelection{{0}, 0});
  ASSERT_EQ(o.fills.size(), 1u);
  EXPECT_EQ(o.fills[0].boundary_edges, 25u);
  EXPECT_FALSE(o.fills[0].failed()) << o.failures();
  EXPECT_EQ(o.cli.code, cli::kOk) << o.cli.err;
}

TEST_F(Topology, AZeroWidthCrackIsStitchedAndWithoutStitchingLeftOpenWithAReason) {
  // A terrain cut along x = 0.5 for 0.3 < y < 0.7: the vertices on the cut are doubled, so the
  // crack is a loop whose two sides lie on top of each other.
  const int n = 11;
  Soup soup = terrain(n);
  std::map<int, int> copy;
  for (auto& f : soup.faces) {
    if (centroid(soup, f)[0] < 0.5) continue;
    for (auto& c : f) {
      const Point p = soup.points[c];
      if (std::abs(p[0] - 0.5) < 1e-9 && p[1] > 0.3 && p[1] < 0.7) {
        if (!copy.count(c)) {
          copy[c] = static_cast<int>(soup.points.size());
          soup.points.push_back(p);
        }
        c = copy[c];
      }
    }
  }
  const Outcome o = fill_file(soup, {}, HoleSelection{{1}, 0}, false);
  EXPECT_EQ(o.report.duplicate_positions, copy.size());
  ASSERT_EQ(o.fills.size(), 1u);
  EXPECT_TRUE(o.fills[0].failed());
  EXPECT_EQ(o.fills[0].failure.kind, FailureKind::CoincidentPoints) << o.fills[0].failure;
  const std::string input = path("input.obj"), output = path("out.obj");
  const CliRun unstitched = run_cli({"fill", input, "-o", output, "--no-stitch", "--holes", "1"});
  EXPECT_EQ(unstitched.code, cli::kSomeHolesNotFilled) << unstitched.err;
  // By default the crack is zipped first: only the terrain's border is left to fill, and every
  // cap across it cuts the bumpy terrain, so it is left open (exit 1).
  const CliRun stitched = run_cli({"fill", input, "-o", output});
  EXPECT_EQ(stitched.code, cli::kSomeHolesNotFilled) << stitched.err;
  EXPECT_NE(stitched.err.find("every patch tried intersects the mesh"), std::string::npos)
      << stitched.err;
  EXPECT_NE(stitched.err.find("stitched 4 boundary edges in 1 seam (3 vertices merged, at most 0 "
                              "apart"),
            std::string::npos)
      << stitched.err;
  EXPECT_NE(stitched.out.find("filled 0 of 1 selected holes (1 in all)"), std::string::npos)
      << stitched.out;
}

TEST_F(Topology, AHoleWhoseEveryTriangulationIsDegenerateIsLeftOpenWithAReasonUnlessStitched) {
  // The inner rim of a band runs out and back along one line through four distinct points, so
  // every triangle across it has zero area.
  Soup soup{
      {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {0, -1, 1}, {1, -1, 1}, {3, 1, 1}, {0, 1, 1}},
      {}};
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    soup.faces.push_back({i, 4 + i, 4 + j});
    soup.faces.push_back({i, 4 + j, j});
  }
  const Outcome o = fill_file(soup);
  const auto line = std::find_if(o.fills.begin(), o.fills.end(), [&](const HoleFill& f) {
    return f.boundary_edges == 4 && o.holes[f.hole_id].vertices[0].idx() < 4;
  });
  ASSERT_NE(line, o.fills.end());
  EXPECT_TRUE(line->failed());
  EXPECT_EQ(line->failure.kind, FailureKind::DegenerateTriangle) << line->failure;
  // The command line stitches first: the rim's way back is one edge with the two middle points
  // inside it, T-junctions, so it is split there and zipped shut, and no hole is left to fail.
  EXPECT_EQ(o.cli.code, cli::kOk) << o.cli.err;
  EXPECT_NE(o.cli.err.find("2 T-junctions split"), std::string::npos) << o.cli.err;
  const Mesh closed = load_mesh(path("out.obj"));
  EXPECT_TRUE(find_holes(closed).empty());  // the outer rim was an ordinary hole
  EXPECT_TRUE(is_oriented_manifold(closed));
}

TEST_F(Topology, AHoleSpanningMostOfTheMeshIsFilled) {
  const Outcome o = fill_file(without(sphere(3), [](const Point& c) { return c[2] > -0.5; }));
  ASSERT_EQ(o.holes.size(), 1u);
  EXPECT_EQ(o.filled(), 1u) << o.failures();
  EXPECT_GT(o.fills[0].boundary_edges, 30u);
  EXPECT_EQ(o.fills[0].self_intersections, 0u);
  EXPECT_TRUE(find_holes(o.after).empty());
  EXPECT_EQ(o.cli.code, cli::kOk) << o.cli.err;
}

TEST_F(Topology, ASingleTriangleIsLeftAloneWithAReason) {
  const Outcome o = fill_file(Soup{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}});
  ASSERT_EQ(o.holes.size(), 1u);
  EXPECT_EQ(o.failed_with(FailureKind::BackOfLoneTriangle), 1u) << o.failures();
  EXPECT_EQ(o.cli.code, cli::kOk) << o.cli.err;
  EXPECT_NE(o.cli.err.find("loop 0 is not a hole but the rim of a lone triangle (face 1)"),
            std::string::npos)
      << o.cli.err;
  EXPECT_EQ(load_mesh(path("out.obj")).n_faces(), 1u);
}

// A cone over a ring of n points: its rim is a hole of n edges.
Soup cone(int n) {
  Soup soup;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    soup.points.emplace_back(std::cos(a), std::sin(a), 0);
  }
  soup.points.emplace_back(0, 0, 1);
  for (int i = 0; i < n; ++i) soup.faces.push_back({i, (i + 1) % n, n});
  return soup;
}

TEST_F(Topology, ATenThousandEdgeHoleIsTriangulatedOrRefusedQuickly) {
  FillOptions options;
  options.last_stage = Stage::Triangulated;
  Outcome o = fill_file(cone(10000), options, {}, false);
  ASSERT_EQ(o.fills.size(), 1u);
  EXPECT_EQ(o.fills[0].boundary_edges, 10000u);
  EXPECT_FALSE(o.fills[0].failed()) << o.failures();
  EXPECT_EQ(o.fills[0].patch.faces.size(), 9998u);
  EXPECT_EQ(o.fills[0].self_intersections, 0u);

  // Without the restricted search, the full dynamic program would take hours: refused at once.
  options.triangulate.restricted.above_edges = 0;
  o = fill_file(cone(10000), options, {}, false);
  ASSERT_EQ(o.fills.size(), 1u);
  EXPECT_EQ(o.fills[0].failure.kind, FailureKind::TooManyEdges) << o.fills[0].failure;
}

}  // namespace
}  // namespace holefill::testing
