// The holefill command on the bundled assets: exit codes, the table, the JSON report, and that
// a failure never leaves a partial output file.
#include <nlohmann/json.hpp>

#include "cli_test_util.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "test_meshes.h"

namespace holefill {
namespace {
using namespace holefill::testing;

TEST_F(Cli, InfoListsTheBunnysThreeHoles) {
  const CliRun run = run_cli({"info", (kAssets / "bunny.obj").string()});
  EXPECT_EQ(run.code, cli::kOk) << run.err;
  EXPECT_NE(run.out.find("3 holes"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("1 components"), std::string::npos) << run.out;
}

TEST_F(Cli, InfoCountsUnusedVerticesApartFromTheComponents) {
  // One triangle and two vertices no face uses: one piece of surface, not three.
  const std::string input = in_dir("unused.obj");
  std::ofstream(input) << "v 0 0 0\nv 1 0 0\nv 5 5 5\nv 0 1 0\nv 6 6 6\nf 1 2 4\n";
  const CliRun run = run_cli({"info", input});
  EXPECT_EQ(run.code, cli::kOk) << run.err;
  EXPECT_NE(run.out.find("5 vertices (2 used by no face), 1 faces, 1 components"),
            std::string::npos)
      << run.out;
  const CliRun json = run_cli({"info", input, "--json"});
  ASSERT_EQ(json.code, cli::kOk) << json.err;
  const auto document = nlohmann::json::parse(json.out);
  EXPECT_EQ(document["components"], 1);
  EXPECT_EQ(document["unused_vertices"], 2);
  EXPECT_EQ(document["vertices"], 5);
}

TEST_F(Cli, FillWritesAClosedMeshAndAReport) {
  const std::string out = in_dir("bunny.ply"), report = in_dir("report.json");
  const CliRun run = run_cli(
      {"fill", (kAssets / "bunny.obj").string(), "-o", out, "--report", report, "--tau", "1.2"});
  ASSERT_EQ(run.code, cli::kOk) << run.err;
  const Mesh before = load_mesh(kAssets / "bunny.obj");
  const Mesh after = load_mesh(out);
  EXPECT_TRUE(find_holes(after).empty());
  EXPECT_GT(after.n_faces(), before.n_faces());
  const std::string json = read_text(report);
  EXPECT_NE(json.find("\"holes\": 0"), std::string::npos) << json;  // none left after
  EXPECT_NE(json.find("\"tau\": 1.2"), std::string::npos);
  EXPECT_NE(json.find("\"valence_histogram\""), std::string::npos);
  // Three per-hole entries, each filled.
  std::size_t filled = 0;
  for (std::size_t at = json.find("\"filled\": true"); at != std::string::npos;
       at = json.find("\"filled\": true", at + 1)) {
    ++filled;
  }
  EXPECT_EQ(filled, 3u);
  EXPECT_FALSE(fs::exists(report + ".partial"));
}

TEST_F(Cli, FillKeepsTheOriginalPartBitForBit) {
  const std::string out = in_dir("sphere.obj");
  ASSERT_EQ(run_cli({"fill", (kAssets / "sphere.obj").string(), "-o", out}).code, cli::kOk);
  EXPECT_TRUE(testing::original_part_unchanged(load_mesh(kAssets / "sphere.obj"), load_mesh(out)));
}

TEST_F(Cli, TheOutputIsTheSameWhateverTheNumberOfThreads) {
  const std::string bunny = (kAssets / "bunny.obj").string();
  const std::string one = in_dir("one.obj"), many = in_dir("many.obj");
  ASSERT_EQ(run_cli({"fill", bunny, "-o", one, "--threads", "1"}).code, cli::kOk);
  ASSERT_EQ(run_cli({"fill", bunny, "-o", many, "--threads", "7"}).code, cli::kOk);
  EXPECT_EQ(read_text(one), read_text(many));
  EXPECT_EQ(run_cli({"fill", bunny, "-o", many, "--threads", "-1"}).code, cli::kUsage);
}

TEST_F(Cli, RemeshOnChangesOnlyThePatchAndIsReported) {
  const std::string bunny = (kAssets / "bunny.obj").string();
  const std::string plain = in_dir("plain.obj"), off = in_dir("off.obj"), on = in_dir("on.obj"),
                    report = in_dir("remesh.json");
  ASSERT_EQ(run_cli({"fill", bunny, "-o", plain}).code, cli::kOk);
  ASSERT_EQ(run_cli({"fill", bunny, "-o", off, "--remesh", "off"}).code, cli::kOk);
  const CliRun run = run_cli({"fill", bunny, "-o", on, "--remesh", "on", "--report", report});
  ASSERT_EQ(run.code, cli::kOk) << run.err;
  EXPECT_EQ(read_text(plain), read_text(off));  // off is the default, byte for byte
  EXPECT_NE(read_text(plain), read_text(on));
  const Mesh before = load_mesh(bunny), remeshed = load_mesh(on);
  EXPECT_TRUE(find_holes(remeshed).empty());
  EXPECT_TRUE(testing::original_part_unchanged(before, remeshed));
  EXPECT_NE(read_text(report).find("\"remesh\": true"), std::string::npos);
}

TEST_F(Cli, SelectedHolesOnly) {
  const std::string out = in_dir("two.obj");
  const CliRun run = run_cli({"fill", (kAssets / "bunny.obj").string(), "-o", out, "--holes", "1,2",
                              "--stage", "triangulate"});
  ASSERT_EQ(run.code, cli::kOk) << run.err;
  const auto holes = find_holes(load_mesh(out));
  ASSERT_EQ(holes.size(), 1u);
  EXPECT_EQ(holes[0].size(), find_holes(load_mesh(kAssets / "bunny.obj"))[0].size());
}

TEST_F(Cli, MaxBoundarySkipsLargerHoles) {
  const std::string out = in_dir("small.obj");
  ASSERT_EQ(
      run_cli({"fill", (kAssets / "bunny.obj").string(), "-o", out, "--max-boundary", "40"}).code,
      cli::kOk);
  EXPECT_EQ(find_holes(load_mesh(out)).size(), 1u);  // the 99-edge hole stays
}

// With a low threshold every bunny hole goes through the restricted search: still all filled, and
// the largest one (99 edges) differently from the full search.
TEST_F(Cli, RestrictedAboveSendsLargerHolesToTheRestrictedSearch) {
  const std::string bunny = (kAssets / "bunny.obj").string();
  const std::string full = in_dir("full.obj"), restricted = in_dir("restricted.obj");
  ASSERT_EQ(run_cli({"fill", bunny, "-o", full, "--stage", "triangulate"}).code, cli::kOk);
  const CliRun run = run_cli(
      {"fill", bunny, "-o", restricted, "--stage", "triangulate", "--restricted-above", "20"});
  ASSERT_EQ(run.code, cli::kOk) << run.err;
  EXPECT_TRUE(find_holes(load_mesh(restricted)).empty());
  EXPECT_NE(read_text(full), read_text(restricted));
}

TEST_F(Cli, UsageErrorsExitWithTwoAndWriteNothing) {
  const std::string bunny = (kAssets / "bunny.obj").string(), out = in_dir("x.obj");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"fill", bunny},
        {"fill", bunny, "-o", out, "--weight", "best"},
        {"fill", bunny, "-o", out, "--tau", "-1"},
        {"fill", bunny, "-o", out, "--tau", "abc"},
        {"fill", bunny, "-o", out, "--holes", "7"},
        {"fill", bunny, "-o", out, "--bogus"},
        {"fill", bunny, "-o", out, "--smooth-iterations", "2.5"},
        {"fill", bunny, "-o", out, "--remesh", "yes"},
        {"fill", bunny, "-o", out, "--remesh"},
        {"fill", bunny, "-o", out, "--restricted-above", "-5"},
        {"fill", bunny, "-o", out, "--restricted-above", "many"},
        {"frobnicate"},
        {"info"}}) {
    const CliRun run = run_cli(args);
    EXPECT_EQ(run.code, cli::kUsage) << args.back();
    EXPECT_FALSE(run.err.empty());
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST_F(Cli, BadInputExitsWithThreeNamingTheFile) {
  const std::string broken = in_dir("broken.obj"), out = in_dir("x.obj");
  std::ofstream(broken) << "v 0 0 0\nv 1 1 nan\nv 0 1 0\nf 1 2 3\n";
  for (const std::string& input : {broken, in_dir("missing.off")}) {
    const CliRun run = run_cli({"fill", input, "-o", out});
    EXPECT_EQ(run.code, cli::kBadInput);
    EXPECT_NE(run.err.find(input), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST_F(Cli, UnwritableOutputExitsWithFourAndLeavesNoPartialFile) {
  const CliRun run =
      run_cli({"fill", (kAssets / "bunny.obj").string(), "-o", in_dir("no/such/dir/x.obj")});
  EXPECT_EQ(run.code, cli::kWriteFailed);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator{}), 0);
}

}  // namespace
}  // namespace holefill
