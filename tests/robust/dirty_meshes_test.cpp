// The dirty meshes end to end through `holefill fill`: each generated mesh has a
// known outcome (holes closed or reported, borders kept, pieces removed), and every output must
// be oriented and manifold, keep the (stitched) input's elements bit for bit, and have no
// degenerate patch triangle.
#include "dirty_meshes.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>

#include "geometry.h"
#include "holefill/components.h"
#include "holefill/holes.h"
#include "holefill/stitch.h"
#include "holefill/triangulate.h"
#include "test_meshes.h"

namespace holefill::testing {
namespace {

struct Filled {
  CliRun cli;
  Mesh before;  // the input as the CLI had it before filling: loaded, stitched, pieces removed
  Mesh after;   // the output file
  nlohmann::json report;  // the --report file
};

class Dirty : public ScratchTest {
 protected:
  Filled fill(const Soup& soup, const std::vector<std::string>& options = {},
              std::size_t remove_pieces_up_to = 0) const {
    const std::string input = write("input.obj", obj_text(soup)).string();
    std::vector<std::string> args{"fill",          input,      "-o",
                                  path("out.obj"), "--report", path("report.json")};
    args.insert(args.end(), options.begin(), options.end());
    Filled f;
    f.cli = run_cli(args);
    f.before = load_mesh(input);
    stitch_borders(f.before);
    if (remove_pieces_up_to) remove_small_pieces(f.before, remove_pieces_up_to);
    if (std::filesystem::exists(path("out.obj"))) f.after = load_mesh(path("out.obj"));
    std::ifstream json(path("report.json"));
    if (json) f.report = nlohmann::json::parse(json);
    return f;
  }
};

// What every output must be, whatever the input's dirt; empty when it is.
std::string problems(const Filled& f) {
  if (!is_oriented_manifold(f.after)) return "the output is not an oriented manifold";
  if (!original_part_unchanged(f.before, f.after)) return "an original element changed";
  for (int i = static_cast<int>(f.before.n_faces()); i < static_cast<int>(f.after.n_faces()); ++i) {
    std::vector<Point> p;
    for (const auto v : f.after.fv_range(FaceHandle(i))) p.push_back(f.after.point(v));
    if (geometry::measure_triangle(p[0], p[1], p[2], false).degenerate)
      return "a degenerate patch face";
  }
  return {};
}

std::set<int> loop_vertices(const Hole& hole) {
  std::set<int> ids;
  for (const auto v : hole.vertices) ids.insert(v.idx());
  return ids;
}

// The loop of `mesh` through the vertex nearest to `near`.
std::set<int> loop_near(const Mesh& mesh, const Point& near) {
  const auto holes = find_holes(mesh);
  std::set<int> best;
  double best_distance = INFINITY;
  for (const auto& hole : holes) {
    for (const auto v : hole.vertices) {
      const double d = (mesh.point(v) - near).norm();
      if (d < best_distance) best_distance = d, best = loop_vertices(hole);
    }
  }
  return best;
}

TEST_F(Dirty, ATerrainWithInteriorHolesKeepsExactlyItsBorderAndClosesEveryHole) {
  Soup soup = terrain_soup(25);
  for (const Point& c : {Point(0.3, 0.3, 0), Point(0.7, 0.4, 0), Point(0.45, 0.75, 0)}) {
    soup =
        without(soup, [&](const Point& p) { return std::hypot(p[0] - c[0], p[1] - c[1]) < 0.1; });
  }
  const Filled f = fill(soup, {"--keep-borders"});
  EXPECT_EQ(f.cli.code, cli::kOk) << f.cli.err;
  EXPECT_EQ(problems(f), "");
  EXPECT_EQ(find_holes(f.before).size(), 4u);
  const auto after = find_holes(f.after);
  ASSERT_EQ(after.size(), 1u);
  EXPECT_EQ(loop_vertices(after[0]), loop_near(f.before, Point(0, 0, 0)));
  EXPECT_NE(f.cli.err.find("loop 0 kept open as a border"), std::string::npos) << f.cli.err;
  EXPECT_EQ(f.report["loops"]["borders_kept"], 1);
}

TEST_F(Dirty, ARuggedTerrainIsStillAHeightFieldWithABorder) {
  // Steep ridges: the surface has several times the area of its footprint.
  Soup soup = soup_of(make_grid(40, [](double x, double y) {
    return 0.3 * std::sin(6 * std::numbers::pi * x) * std::sin(6 * std::numbers::pi * y);
  }));
  soup = without(soup, [](const Point& c) { return std::hypot(c[0] - 0.5, c[1] - 0.5) < 0.12; });
  const Filled f = fill(soup, {"--keep-borders"});
  EXPECT_EQ(problems(f), "");
  ASSERT_EQ(find_holes(f.after).size(), 1u);
  EXPECT_EQ(loop_vertices(find_holes(f.after)[0]), loop_near(f.before, Point(0, 0, 0)));
  EXPECT_NE(f.cli.err.find("like a height field"), std::string::npos) << f.cli.err;
}

TEST_F(Dirty, DomesWithHolesKeepTheirRimAndCloseTheHoles) {
  for (const double bottom : {0.0, 0.4}) {
    Soup soup = dome_soup(3, bottom);
    soup = with_hole(soup, Point(0, 0, 1), 0.25);
    soup = with_hole(soup, Point(0.75, 0, 0.66), 0.2);
    const Filled f = fill(soup, {"--keep-borders"});
    EXPECT_EQ(f.cli.code, cli::kOk) << f.cli.err;
    EXPECT_EQ(problems(f), "");
    const auto after = find_holes(f.after);
    ASSERT_EQ(after.size(), 1u) << "bottom " << bottom << "\n" << f.cli.err;
    EXPECT_EQ(loop_vertices(after[0]), loop_near(f.before, Point(0, -1, bottom)));
  }
}

// A piece floating in a hole is filled with it (islands.h), though its rim on its own looks like
// a border: --keep-borders said it kept that loop open, and then filled it (issue 32, #8). With
// --islands off the piece is no island: its rim is kept open and said so.
TEST_F(Dirty, AnIslandThatLooksLikeABorderIsFilledWithItsHoleAndNotSaidToBeKept) {
  const Point top(0, 0, 1);
  const Soup soup = without(sphere_soup(3), [&](const Point& c) {
    const double d = (c - top).norm();
    return d > 0.2 && d < 0.6;
  });
  Filled f = fill(soup, {"--keep-borders"});
  ASSERT_EQ(find_holes(f.before).size(), 2u);
  EXPECT_EQ(f.cli.code, cli::kOk) << f.cli.err;
  EXPECT_EQ(problems(f), "");
  EXPECT_TRUE(find_holes(f.after).empty()) << f.cli.err;
  EXPECT_EQ(f.cli.err.find("kept open"), std::string::npos) << f.cli.err;
  EXPECT_EQ(f.report["loops"]["borders_kept"], 0);

  f = fill(soup, {"--keep-borders", "--islands", "off"});
  EXPECT_EQ(problems(f), "");
  const auto after = find_holes(f.after);
  ASSERT_EQ(after.size(), 1u) << f.cli.err;
  EXPECT_EQ(loop_vertices(after[0]), loop_near(f.before, top));
  EXPECT_NE(f.cli.err.find("kept open as a border"), std::string::npos) << f.cli.err;
  EXPECT_EQ(f.report["loops"]["borders_kept"], 1);
}

TEST_F(Dirty, ClosedSurfacesHaveNoBorderToKeep) {
  // A sphere with a large and a small hole, and a sphere cut below its equator (a deep bowl).
  Soup sphere = with_hole(with_hole(sphere_soup(3), Point(1, 0, 0), 0.5), Point(0, 0, 1), 0.2);
  Filled f = fill(sphere, {"--keep-borders"});
  EXPECT_EQ(f.cli.code, cli::kOk) << f.cli.err;
  EXPECT_EQ(problems(f), "");
  EXPECT_TRUE(find_holes(f.after).empty());

  f = fill(without(sphere_soup(3), [](const Point& c) { return c[2] > 0.5; }), {"--keep-borders"});
  EXPECT_EQ(problems(f), "");
  EXPECT_TRUE(find_holes(f.after).empty()) << f.cli.err;

  const std::string bunny = std::string(HOLEFILL_ASSETS_DIR) + "/bunny.obj";
  const CliRun run = run_cli({"fill", bunny, "-o", path("bunny.obj"), "--keep-borders"});
  EXPECT_EQ(run.code, cli::kOk) << run.err;
  EXPECT_TRUE(find_holes(load_mesh(path("bunny.obj"))).empty());
}

TEST_F(Dirty, LoneTrianglesAndSmallPiecesAreToldApartAndRemovedOnRequest) {
  Soup soup = with_hole(sphere_soup(3), Point(0, 0, 1), 0.3);
  for (int i = 0; i < 3; ++i) {
    const Point o(3 + i, 0, 0);
    soup = append(soup, Soup{{o, o + Point(0.1, 0, 0), o + Point(0, 0.1, 0)}, {{0, 1, 2}}});
  }
  // A bent strip of four faces: not flat, so its rim is a hole like any other; but every cap across
  // it lies on the strip's back, so it is left open (do no harm).
  soup = append(soup, Soup{{{0, 3, 0}, {1, 3, 0}, {2, 3, 0}, {0, 4, 0.2}, {1, 4, 0.5}, {2, 4, 0.1}},
                           {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}}});
  Filled f = fill(soup);
  EXPECT_EQ(problems(f), "");
  EXPECT_NE(f.cli.err.find("3 lone triangles and 1 small floating piece beside the surface, of "
                           "at most 4 faces; --remove-small-components 4 removes them"),
            std::string::npos)
      << f.cli.err;
  EXPECT_EQ(find_holes(f.after).size(), 4u);  // the triangles' rims (not holes) and the strip's
  EXPECT_NE(f.cli.err.find("every patch tried intersects the mesh"), std::string::npos)
      << f.cli.err;
  EXPECT_EQ(f.report["pieces"]["lone_triangles"], 3);
  EXPECT_EQ(f.report["pieces"]["small_pieces"], 1);

  f = fill(soup, {"--remove-small-components", "4"}, 4);
  EXPECT_EQ(f.cli.code, cli::kOk) << f.cli.err;
  EXPECT_EQ(problems(f), "");
  EXPECT_NE(f.cli.err.find("removed 4 pieces of at most 4 faces (7 faces, 15 vertices)"),
            std::string::npos)
      << f.cli.err;
  EXPECT_TRUE(find_holes(f.after).empty());
  EXPECT_EQ(mesh_pieces(f.after).pieces.size(), 1u);
}

TEST_F(Dirty, ALoopThroughOneVertexTooOftenNamesTheFlagThatRemovesSmallPieces) {
  // 20 lone triangles around one vertex: one loop through it 20 times, refused (the core's
  // kMaxVertexPasses is 16); the core says why, the command adds its own flag.
  Mesh fan;
  const VertexHandle centre = fan.add_vertex(Point(0.0, 0.0, 0.0));
  for (int i = 0; i < 20; ++i) {
    const double a = 2.0 * std::numbers::pi * i / 20, b = 2.0 * std::numbers::pi * (i + 0.5) / 20;
    const VertexHandle p = fan.add_vertex(Point(std::cos(a), std::sin(a), 0.01 * (i % 7)));
    const VertexHandle q = fan.add_vertex(Point(std::cos(b), std::sin(b), 0.01 * (i % 5)));
    fan.add_face(centre, p, q);
  }
  save_mesh(fan, path("fan.obj"));
  const CliRun run = run_cli({"fill", path("fan.obj"), "-o", path("out.obj")});
  EXPECT_EQ(run.code, cli::kSomeHolesNotFilled) << run.err;
  EXPECT_NE(run.err.find("times, more than the 16 a patch is planned for (kMaxVertexPasses): it "
                         "runs around pieces that meet only there, not around a hole; "
                         "--remove-small-components N removes pieces of at most N faces"),
            std::string::npos)
      << run.err;
}

TEST_F(Dirty, ASphereCutIntoPiecesWithHairlineCracksIsStitchedAndItsHoleFilled) {
  Soup soup = with_hole(sphere_soup(3), Point(0, 0, -1), 0.3);
  std::mt19937 rng(7);
  const std::size_t copies = cut_apart(
      soup, [](const Point& c) { return c[0] + 0.2 * c[1] > 0.1; }, 1e-7, rng);
  const Filled f = fill(soup);
  EXPECT_EQ(f.cli.code, cli::kOk) << f.cli.err;
  EXPECT_EQ(problems(f), "");
  EXPECT_TRUE(find_holes(f.after).empty());
  EXPECT_EQ(f.report["stitch"]["vertices_merged"], copies);
  EXPECT_EQ(f.report["loops"]["count"], 1);

  // Without stitching, each piece's side of the cut (which runs through the hole) is a loop.
  const Filled unstitched = fill(soup, {"--no-stitch", "--stage", "triangulate"});
  EXPECT_TRUE(unstitched.report["stitch"].is_null());
  EXPECT_EQ(unstitched.report["loops"]["count"], 2);
}

}  // namespace
}  // namespace holefill::testing
