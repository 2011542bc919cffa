// `holefill info` and `fill` with sharp features (features.h): info names the features entering a
// hole, fill continues a cube's edge through a hole and reports it, --feature-angle 0 turns it off.
#include <nlohmann/json.hpp>

#include "cad_parts.h"
#include "cli_test_util.h"
#include "holefill/io.h"
#include "island_meshes.h"
#include "test_meshes.h"

namespace holefill {
namespace {
using namespace holefill::testing;

// The unit cube (ten grid squares along each edge) with a hole across its edge y = z = 0.
std::string write_cube_with_edge_hole(const std::string& path) {
  const auto lines = grid_lines({{0.1, 10}});
  const Mesh cube = surface_of({lines, lines, lines, [](int, int, int) { return true; }});
  save_mesh(without_isolated_vertices(without_faces(
                cube, [](const Point& c) { return (c - Point(0.5, 0, 0)).norm() < 0.25; })),
            path);
  return path;
}

TEST_F(Cli, InfoNamesTheFeaturesEnteringAHole) {
  const std::string input = write_cube_with_edge_hole(in_dir("cube.obj"));
  const CliRun run = run_cli({"info", input});
  ASSERT_EQ(run.code, cli::kOk) << run.err;
  EXPECT_NE(run.out.find("features: 2 lines, crease"), std::string::npos) << run.out;
  const CliRun off = run_cli({"info", input, "--feature-angle", "0"});
  ASSERT_EQ(off.code, cli::kOk) << off.err;
  EXPECT_EQ(off.out.find("features"), std::string::npos) << off.out;
  const CliRun json = run_cli({"info", input, "--json"});
  ASSERT_EQ(json.code, cli::kOk) << json.err;
  const auto features = nlohmann::json::parse(json.out)["holes"][0]["features"];
  EXPECT_EQ(features["lines"], 2);
  EXPECT_EQ(features["junctions"][0]["kind"], "crease");
}

TEST_F(Cli, FillContinuesACubesEdgeAndReportsIt) {
  const std::string input = write_cube_with_edge_hole(in_dir("cube.obj"));
  const std::string out = in_dir("filled.obj"), report = in_dir("report.json");
  const CliRun run = run_cli({"fill", input, "-o", out, "--report", report});
  ASSERT_EQ(run.code, cli::kOk) << run.err;
  const auto json = nlohmann::json::parse(read_text(report));
  EXPECT_EQ(json["options"]["feature_angle_deg"], 40.0);
  const auto features = json["holes"][0]["features"];
  EXPECT_EQ(features["continued"], true);
  EXPECT_EQ(features["junctions"][0]["kind"], "crease");
  // Every vertex of the filled cube lies on its surface: the edge came back sharp.
  const Mesh after = load_mesh(out);
  for (const auto v : after.vertices()) {
    const Point& p = after.point(v);
    const double to_surface = std::min({p[0], p[1], p[2], 1 - p[0], 1 - p[1], 1 - p[2]});
    EXPECT_LT(std::abs(to_surface), 1e-9) << p;
  }
  const CliRun off =
      run_cli({"fill", input, "-o", out, "--report", report, "--feature-angle", "0"});
  ASSERT_EQ(off.code, cli::kOk) << off.err;
  EXPECT_FALSE(nlohmann::json::parse(read_text(report))["holes"][0].contains("features"));
}

TEST_F(Cli, AFeatureAngleOutOfRangeIsAUsageError) {
  const std::string input = write_cube_with_edge_hole(in_dir("cube.obj"));
  EXPECT_EQ(run_cli({"fill", input, "-o", in_dir("x.obj"), "--feature-angle", "-1"}).code,
            cli::kUsage);
  EXPECT_EQ(run_cli({"info", input, "--feature-angle", "200"}).code, cli::kUsage);
}

}  // namespace
}  // namespace holefill
