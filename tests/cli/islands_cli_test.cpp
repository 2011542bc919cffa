// `holefill info` and `fill` with islands and bridges: info names the islands, fill closes a hole
// with its island by default and each loop alone with --islands off, --bridge joins two holes,
// and a bridge that cannot be built leaves the holes open with the reason.
#include <nlohmann/json.hpp>

#include "cli_test_util.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "holefill/stats.h"
#include "island_meshes.h"
#include "test_meshes.h"

namespace holefill {
namespace {
using namespace holefill::testing;

// A sphere with an annulus cut around a cap left floating in it, written to `path`.
std::string write_sphere_with_island(const std::string& path) {
  save_mesh(cut_around_islands(make_blob(3, [](const Point&) { return 1.0; }),
                               {Point(0, 0, 1), 0.8}, {{Point(0, 0, 1), 0.35}}),
            path);
  return path;
}

// The unit sphere without the band |z| < half_gap: two caps facing each other.
std::string write_cut_sphere(const std::string& path, double half_gap) {
  save_mesh(without_isolated_vertices(without_faces(
                make_icosphere(3), [=](const Point& c) { return std::abs(c[2]) < half_gap; })),
            path);
  return path;
}

TEST_F(Cli, InfoNamesTheIslandsOfAHole) {
  const CliRun run = run_cli({"info", write_sphere_with_island(in_dir("island.obj"))});
  EXPECT_EQ(run.code, cli::kOk) << run.err;
  EXPECT_NE(run.out.find("2 components"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("islands 1"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("island of 0"), std::string::npos) << run.out;
  const CliRun json = run_cli({"info", in_dir("island.obj"), "--json"});
  ASSERT_EQ(json.code, cli::kOk) << json.err;
  const auto holes = nlohmann::json::parse(json.out)["holes"];
  EXPECT_EQ(holes[0]["islands"], nlohmann::json::array({1}));
  EXPECT_EQ(holes[1]["island_of"], 0);
}

// info can skip island detection as fill can (its cost grows with the loops' lengths).
TEST_F(Cli, InfoWithIslandsOffNamesNoIsland) {
  const std::string input = write_sphere_with_island(in_dir("island.obj"));
  const CliRun run = run_cli({"info", input, "--islands", "off"});
  EXPECT_EQ(run.code, cli::kOk) << run.err;
  EXPECT_NE(run.out.find("2 holes"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("islands 1"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("island of"), std::string::npos) << run.out;
  const CliRun json = run_cli({"info", input, "--json", "--islands", "off"});
  ASSERT_EQ(json.code, cli::kOk) << json.err;
  const auto holes = nlohmann::json::parse(json.out)["holes"];
  ASSERT_EQ(holes.size(), 2u);
  for (const auto& hole : holes) {
    EXPECT_EQ(hole["islands"], nlohmann::json::array());
    EXPECT_FALSE(hole.contains("island_of"));
  }
  EXPECT_EQ(run_cli({"info", input, "--islands", "maybe"}).code, cli::kUsage);
}

TEST_F(Cli, FillClosesAHoleWithItsIslandByDefault) {
  const std::string input = write_sphere_with_island(in_dir("island.obj"));
  const std::string out = in_dir("filled.obj"), report = in_dir("report.json");
  const CliRun run = run_cli({"fill", input, "-o", out, "--report", report});
  ASSERT_EQ(run.code, cli::kOk) << run.err;
  const Mesh after = load_mesh(out);
  EXPECT_TRUE(find_holes(after).empty());
  EXPECT_EQ(connected_components(after), 1u);
  EXPECT_EQ(euler_characteristic(after), 2);
  const auto json = nlohmann::json::parse(read_text(report));
  EXPECT_EQ(json["options"]["islands"], "on");
  ASSERT_EQ(json["holes"].size(), 1u);
  EXPECT_EQ(json["holes"][0]["joined_holes"], nlohmann::json::array({1}));
}

TEST_F(Cli, IslandsOffFillsEachLoopOnItsOwn) {
  const std::string input = write_sphere_with_island(in_dir("island.obj"));
  const std::string out = in_dir("filled.obj");
  const CliRun run = run_cli({"fill", input, "-o", out, "--islands", "off"});
  ASSERT_EQ(run.code, cli::kOk) << run.err;
  const Mesh after = load_mesh(out);
  EXPECT_TRUE(find_holes(after).empty());
  EXPECT_EQ(connected_components(after), 2u);
}

TEST_F(Cli, BridgeJoinsTwoHolesIntoOneSurface) {
  const std::string input = write_cut_sphere(in_dir("cut.obj"), 0.3);
  const std::string out = in_dir("bridged.obj");
  const CliRun run = run_cli({"fill", input, "-o", out, "--bridge", "0,1"});
  ASSERT_EQ(run.code, cli::kOk) << run.err;
  const Mesh after = load_mesh(out);
  EXPECT_TRUE(find_holes(after).empty());
  EXPECT_EQ(connected_components(after), 1u);
  EXPECT_EQ(euler_characteristic(after), 2);
}

TEST_F(Cli, ABridgeTooLongLeavesBothHolesOpenWithTheReason) {
  const std::string input = write_cut_sphere(in_dir("cut.obj"), 0.97);
  const std::string out = in_dir("bridged.obj");
  const CliRun run = run_cli({"fill", input, "-o", out, "--bridge", "0,1"});
  EXPECT_EQ(run.code, cli::kSomeHolesNotFilled) << run.err;
  EXPECT_NE(run.err.find("too far apart to bridge"), std::string::npos) << run.err;
  EXPECT_EQ(find_holes(load_mesh(out)).size(), 2u);
}

TEST_F(Cli, BridgeNeedsTwoExistingHoleIds) {
  const std::string input = write_cut_sphere(in_dir("cut.obj"), 0.3);
  // "0,0" was taken, then not filled (exit 1): "a bridge needs two different holes".
  for (const std::string bad : {"0", "0,7", "0,x", "0,1,2", "0,0", "1,1"}) {
    const CliRun run = run_cli({"fill", input, "-o", in_dir("out.obj"), "--bridge", bad});
    EXPECT_EQ(run.code, cli::kUsage) << bad;
    EXPECT_NE(run.err.find("--bridge"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(in_dir("out.obj")));
  }
}

// --max-boundary below the bridged loops' edges left the bridge (and both holes) out of the fill
// without a word, exit 0.
TEST_F(Cli, ABridgeThatMaxBoundaryExcludesIsAUsageError) {
  const std::string input = write_cut_sphere(in_dir("cut.obj"), 0.3);
  const auto holes = find_holes(load_mesh(input));
  ASSERT_EQ(holes.size(), 2u);
  const std::size_t edges = holes[0].size() + holes[1].size();
  const std::string out = in_dir("out.obj");
  const CliRun run = run_cli(
      {"fill", input, "-o", out, "--bridge", "0,1", "--max-boundary", std::to_string(edges - 1)});
  EXPECT_EQ(run.code, cli::kUsage) << run.err;
  EXPECT_NE(run.err.find("--bridge 0,1: holes 0 and 1 have " + std::to_string(edges) +
                         " boundary edges together, more than --max-boundary " +
                         std::to_string(edges - 1) + " fills"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(out));
  const CliRun enough = run_cli(
      {"fill", input, "-o", out, "--bridge", "0,1", "--max-boundary", std::to_string(edges)});
  EXPECT_EQ(enough.code, cli::kOk) << enough.err;
  EXPECT_TRUE(find_holes(load_mesh(out)).empty());
}

}  // namespace
}  // namespace holefill
