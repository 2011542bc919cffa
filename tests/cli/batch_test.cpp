// holefill fill over many meshes at once: a line per mesh and a total, the worst mesh's exit
// code, broken meshes beside good ones, and outputs byte for byte those of one fill per mesh.
#include <algorithm>
#include <nlohmann/json.hpp>
#include <utility>

#include "batch_command.h"
#include "cli_test_util.h"
#include "holefill/cores.h"

namespace holefill {
namespace {
using namespace holefill::testing;

std::size_t count_of(const std::string& text, const std::string& part) {
  std::size_t count = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
  return count;
}

class Batch : public Cli {
 protected:
  // Good meshes, a broken one, an empty one and a missing one, in a folder of their own.
  std::vector<std::string> make_inputs() {
    fs::create_directories(dir_ / "in");
    std::vector<std::string> inputs;
    for (const char* name : {"bunny.obj", "torus.obj", "sphere.obj"}) {
      fs::copy_file(kAssets / name, dir_ / "in" / name);
      inputs.push_back((dir_ / "in" / name).string());
    }
    std::ofstream(dir_ / "in" / "broken.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n";
    std::ofstream(dir_ / "in" / "empty.ply");
    inputs.push_back((dir_ / "in" / "broken.off").string());
    inputs.push_back((dir_ / "in" / "empty.ply").string());
    inputs.push_back((dir_ / "in" / "missing.stl").string());
    return inputs;
  }
};

TEST_F(Batch, BrokenMeshesGetALineEachAndTheWorstCodeWithoutStoppingTheOthers) {
  const auto inputs = make_inputs();
  std::vector<std::string> args{"fill", "-j", "2"};
  args.insert(args.end(), inputs.begin(), inputs.end());
  args.insert(args.end(), {"-o", in_dir("out") + "/", "--report", in_dir("batch.json")});
  const CliRun run = run_cli(args);
  EXPECT_EQ(run.code, cli::kBadInput) << run.out << run.err;
  for (const auto& input : inputs) EXPECT_EQ(count_of(run.out, input + ": "), 1u) << run.out;
  EXPECT_EQ(count_of(run.out, "(exit 0)"), 3u) << run.out;
  EXPECT_EQ(count_of(run.out, "(exit 3)"), 3u) << run.out;
  EXPECT_NE(run.out.find("total: 6 meshes, 3 exit 0, 3 exit 3 in "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("broken.off: not filled: "), std::string::npos) << run.out;
  for (const char* name : {"bunny.obj", "torus.obj", "sphere.obj"}) {
    EXPECT_TRUE(fs::exists(dir_ / "out" / name)) << name;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out" / "broken.off"));
  const auto report = nlohmann::json::parse(read_text(in_dir("batch.json")));
  EXPECT_EQ(report["exit_code"], 3);
  ASSERT_EQ(report["meshes"].size(), 6u);
  EXPECT_EQ(report["meshes"][0]["report"]["after"]["holes"], 0);
  EXPECT_TRUE(report["meshes"][3]["report"].is_null());
  EXPECT_EQ(report["meshes"][3]["exit_code"], 3);
}

TEST_F(Batch, OutputsAreThoseOfOneFillPerMeshByteForByte) {
  const auto inputs = make_inputs();
  const CliRun run = run_cli(
      {"fill", "-q", in_dir("in"), "-o", in_dir("out") + "/", "--tau", "1.0", "--format", "ply"});
  EXPECT_EQ(run.code, cli::kBadInput) << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out;
  for (const char* name : {"bunny", "torus", "sphere"}) {
    const std::string single = in_dir(std::string(name) + "-single.ply");
    const CliRun one = run_cli({"fill", "-q", (dir_ / "in" / (std::string(name) + ".obj")).string(),
                                "-o", single, "--tau", "1.0"});
    ASSERT_EQ(one.code, cli::kOk) << one.err;
    EXPECT_EQ(read_text(dir_ / "out" / (std::string(name) + ".ply")), read_text(single)) << name;
  }
}

TEST_F(Batch, TheWorstCodeIsTheMostSevereNotTheLargest) {
  // A mesh without the hole asked for is a usage error (ragged_disk has two loops).
  const CliRun usage =
      run_cli({"fill", (kAssets / "ragged_disk.obj").string(), (kAssets / "bunny.obj").string(),
               "-o", in_dir("out"), "--holes", "2"});
  EXPECT_EQ(usage.code, cli::kUsage) << usage.out << usage.err;
  EXPECT_NE(usage.out.find("ragged_disk.obj: not filled: --holes: "), std::string::npos)
      << usage.out;
  // An output that cannot be written (a folder is in its place) is exit 4, a broken mesh exit 3:
  // the batch's code is 3, the more severe.
  const auto inputs = make_inputs();
  fs::create_directories(dir_ / "out2" / "bunny.obj");
  const CliRun mixed = run_cli({"fill", inputs[0], inputs[3], "-o", in_dir("out2")});
  EXPECT_NE(mixed.out.find("(exit 4)"), std::string::npos) << mixed.out << mixed.err;
  EXPECT_EQ(mixed.code, cli::kBadInput) << mixed.out << mixed.err;
}

TEST_F(Batch, EachMeshGetsItsShareOfTheCoresUnlessThreadsAreGiven) {
  // The split: cores / jobs, at least one; --threads as given.
  EXPECT_EQ(cli::threads_per_mesh(0, 4, 16), 4u);
  EXPECT_EQ(cli::threads_per_mesh(0, 3, 16), 5u);
  EXPECT_EQ(cli::threads_per_mesh(0, 16, 16), 1u);
  EXPECT_EQ(cli::threads_per_mesh(0, 1, 16), 16u);
  EXPECT_EQ(cli::threads_per_mesh(0, 8, 2), 1u);
  EXPECT_EQ(cli::threads_per_mesh(5, 4, 16), 5u);
  // It reaches each mesh's fill (its report's options), and the outputs are the same whatever
  // the split: one mesh at a time on every core, three at once on a share, one thread each.
  const auto inputs = make_inputs();
  const std::vector<std::string> good(inputs.begin(), inputs.begin() + 3);
  const unsigned cores = available_cores();
  const std::vector<std::pair<std::vector<std::string>, unsigned>> runs{
      {{"-j", "1"}, cores},
      {{"-j", "3"}, std::max(1u, cores / 3)},
      {{"-j", "3", "--threads", "1"}, 1u},
      {{}, std::max(1u, cores / std::min(cores, 3u))}};  // -j: one per core, at most one per mesh
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const std::string out = in_dir("out" + std::to_string(r));
    std::vector<std::string> args{"fill", "-q"};
    args.insert(args.end(), good.begin(), good.end());
    args.insert(args.end(), {"-o", out + "/", "--report", out + ".json"});
    args.insert(args.end(), runs[r].first.begin(), runs[r].first.end());
    const CliRun run = run_cli(args);
    ASSERT_EQ(run.code, cli::kOk) << run.err;
    const auto report = nlohmann::json::parse(read_text(out + ".json"));
    for (const auto& mesh : report["meshes"]) {
      EXPECT_EQ(mesh["report"]["options"]["threads"], runs[r].second) << r;
    }
    for (const char* name : {"bunny.obj", "torus.obj", "sphere.obj"}) {
      EXPECT_EQ(read_text(fs::path(out) / name), read_text(dir_ / "out0" / name)) << r << name;
    }
  }
}

TEST_F(Batch, TwoMeshesOfOneNameAreRefusedBeforeAnyWork) {
  fs::create_directories(dir_ / "a");
  fs::copy_file(kAssets / "bunny.obj", dir_ / "a" / "bunny.obj");
  const CliRun run = run_cli({"fill", (kAssets / "bunny.obj").string(),
                              (dir_ / "a" / "bunny.obj").string(), "-o", in_dir("out")});
  EXPECT_EQ(run.code, cli::kUsage);
  EXPECT_NE(run.err.find("would both be written to"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "bunny.obj"));
}

}  // namespace
}  // namespace holefill
