// Where fill's results go: outputs checked before the work, the report never replacing the input
// or the mesh, which output failed and why, standard output as a destination and as a failure.
#include <nlohmann/json.hpp>

#include "cli_test_util.h"
#include "holefill/holes.h"
#include "holefill/io.h"

namespace holefill {
namespace {
using namespace holefill::testing;

// --report equal to the input replaced the mesh with JSON, exit 0.
TEST_F(Cli, AReportNamingTheInputOrTheMeshOutputIsRefused) {
  const std::string input = in_dir("in.obj"), out = in_dir("out.obj");
  fs::copy_file(bunny(), input);
  fs::create_symlink("in.obj", in_dir("link.obj"));
  fs::create_hard_link(input, in_dir("hard.obj"));
  fs::create_symlink("out.obj", in_dir("out-link.json"));
  const std::string original = read_text(input);
  for (const auto& [output, report] :
       std::vector<std::pair<std::string, std::string>>{{out, input},
                                                        {out, in_dir("./in.obj")},
                                                        {out, in_dir("link.obj")},
                                                        {out, in_dir("hard.obj")},
                                                        {out, in_dir("out-link.json")}}) {
    const CliRun run = run_cli({"fill", input, "-o", output, "--report", report});
    EXPECT_EQ(run.code, cli::kUsage) << report;
    EXPECT_NE(run.err.find("--report"), std::string::npos) << run.err;
    EXPECT_EQ(read_text(input), original);
    EXPECT_FALSE(fs::exists(out));
  }
}

// -o naming the input (by any path to the same file) would lose the original mesh: refused before
// the work, the input untouched.
TEST_F(Cli, AMeshOutputNamingTheInputIsRefused) {
  const std::string input = in_dir("in.obj");
  fs::copy_file(bunny(), input);
  fs::create_symlink("in.obj", in_dir("link.obj"));
  fs::create_hard_link(input, in_dir("hard.obj"));
  const std::string original = read_text(input);
  for (const std::string& output :
       {input, in_dir("./in.obj"), in_dir("link.obj"), in_dir("hard.obj")}) {
    const CliRun run = run_cli({"fill", input, "-o", output});
    EXPECT_EQ(run.code, cli::kUsage) << output;
    EXPECT_NE(run.err.find("is the input mesh"), std::string::npos) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
    EXPECT_EQ(read_text(input), original);
  }
}

// A missing output folder was found only after the whole fill.
TEST_F(Cli, AnOutputThatCannotBeWrittenIsFoundBeforeTheWork) {
  for (const auto& args :
       {std::vector<std::string>{"fill", bunny(), "-o", in_dir("no/x.obj")},
        {"fill", bunny(), "-o", in_dir("x.obj"), "--report", in_dir("no/r.json")}}) {
    const CliRun run = run_cli(args);
    EXPECT_EQ(run.code, cli::kWriteFailed);
    EXPECT_NE(run.err.find("folder does not exist"), std::string::npos) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;  // no table: nothing was filled
    EXPECT_FALSE(fs::exists(in_dir("x.obj")));
  }
}

// A report that could not be written gave exit 4 without saying the mesh had been written.
TEST_F(Cli, AReportThatCannotBeWrittenSaysWhichOutputFailedAndWhy) {
  fs::create_symlink("/dev/full", in_dir("full.json"));
  const std::string out = in_dir("x.obj");
  const CliRun run = run_cli({"fill", bunny(), "-o", out, "--report", in_dir("full.json")});
  EXPECT_EQ(run.code, cli::kWriteFailed);
  EXPECT_NE(run.err.find("No space left on device"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("the report was not written (the filled mesh was, to " + out),
            std::string::npos)
      << run.err;
  EXPECT_TRUE(find_holes(load_mesh(out)).empty());
}

// A stream that refuses every write, as a closed pipe or a full disk does.
class RefusingBuffer : public std::streambuf {
 protected:
  int_type overflow(int_type) override { return traits_type::eof(); }
  std::streamsize xsputn(const char*, std::streamsize) override { return 0; }
};

// `holefill fill ... | head -1` lost the mesh; `info > /dev/full` exited 0.
TEST_F(Cli, AFailingStandardOutputIsReportedAfterTheFilesAreWritten) {
  RefusingBuffer refusing;
  std::ostream out(&refusing);
  std::istringstream in;
  std::ostringstream err;
  const std::string mesh = in_dir("x.obj");
  EXPECT_EQ(cli::run({"fill", bunny(), "-o", mesh}, in, out, err), cli::kWriteFailed);
  EXPECT_NE(err.str().find("standard output could not be written"), std::string::npos);
  EXPECT_TRUE(find_holes(load_mesh(mesh)).empty());
  out.clear();
  EXPECT_EQ(cli::run({"info", bunny()}, in, out, err), cli::kWriteFailed);
  out.clear();
  EXPECT_EQ(cli::run({"--version"}, in, out, err), cli::kWriteFailed);
}

TEST_F(Cli, MinusReadsStandardInputAndWritesStandardOutput) {
  std::istringstream in(read_text(bunny()));
  std::ostringstream out, err;
  ASSERT_EQ(
      cli::run({"fill", "-", "--format", "obj", "-o", "-", "--stage", "triangulate"}, in, out, err),
      cli::kOk)
      << err.str();
  const Mesh filled = load_mesh_from_memory(out.str(), "filled.obj");
  EXPECT_TRUE(find_holes(filled).empty());
  EXPECT_NE(err.str().find("filled 3 of 3"), std::string::npos) << err.str();  // the table
  EXPECT_EQ(run_cli({"fill", "-", "-o", in_dir("x.obj")}).code, cli::kUsage);  // no --format
  EXPECT_EQ(run_cli({"fill", bunny(), "-o", "-"}).code, cli::kUsage);
}

TEST_F(Cli, TheReportCanGoToStandardOutput) {
  const CliRun run = run_cli({"fill", bunny(), "-o", in_dir("x.obj"), "--report", "-"});
  ASSERT_EQ(run.code, cli::kOk) << run.err;
  const auto report = nlohmann::json::parse(run.out);
  EXPECT_EQ(report["after"]["holes"], 0);
  EXPECT_EQ(run_cli({"fill", bunny(), "-o", "-", "--format", "obj", "--report", "-"}).code,
            cli::kUsage);
}

// A file name that is not UTF-8 produced invalid JSON, exit 0.
TEST_F(Cli, JsonIsValidWhateverTheFileNames) {
  const std::string input = in_dir("bunny-\xff\xfe.obj"), report = in_dir("r.json");
  fs::copy_file(bunny(), input);
  const CliRun fill = run_cli({"fill", input, "-o", in_dir("out.obj"), "--report", report});
  ASSERT_EQ(fill.code, cli::kOk) << fill.err;
  const auto parsed = nlohmann::json::parse(read_text(report));  // throws on invalid UTF-8
  EXPECT_EQ(parsed["holes"].size(), 3u);
  EXPECT_NE(parsed["input"].get<std::string>().find("bunny-\xef\xbf\xbd"), std::string::npos);

  const CliRun info = run_cli({"info", "--json", input});
  ASSERT_EQ(info.code, cli::kOk) << info.err;
  const auto described = nlohmann::json::parse(info.out);
  const Mesh mesh = load_mesh(bunny());
  const auto holes = find_holes(mesh);
  EXPECT_EQ(described["vertices"], mesh.n_vertices());
  EXPECT_EQ(described["faces"], mesh.n_faces());
  ASSERT_EQ(described["holes"].size(), holes.size());
  EXPECT_EQ(described["holes"][0]["boundary_edges"], holes[0].size());
  EXPECT_DOUBLE_EQ(described["holes"][0]["perimeter"].get<double>(), holes[0].perimeter);
}

// `info` columns merged for huge values ("31.23457e+150").
TEST_F(Cli, InfoColumnsStayApartForHugeValues) {
  const std::string huge = in_dir("huge.obj");
  std::ofstream(huge) << "v 0 0 0\nv 1.23456789e150 0 0\nv 0 1.23456789e150 0\n"
                         "v 0 0 1.23456789e150\nf 1 3 2\nf 1 2 4\nf 2 3 4\n";
  const CliRun run = run_cli({"info", huge});
  ASSERT_EQ(run.code, cli::kOk) << run.err;
  std::istringstream rows(run.out.substr(run.out.rfind("note\n") + 5));
  std::string id, edges, perimeter;
  rows >> id >> edges >> perimeter;
  EXPECT_EQ(id, "0");
  EXPECT_EQ(edges, "3");
  EXPECT_NEAR(std::stod(perimeter) / ((2.0 + std::sqrt(2.0)) * 1.23456789e150), 1.0, 1e-5);
}

}  // namespace
}  // namespace holefill
