// Replays every seed and corpus input of the fuzzers and every crash they found
// (tests/fuzz/seeds/<target>/, tests/fuzz/corpus/<target>/, tests/fuzz/regressions/<target>-*)
// through the same checks the libFuzzer targets make, so that a fixed crash stays fixed without
// clang or libFuzzer.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fuzz_inputs.h"

namespace holefill::fuzz {
namespace {
namespace fs = std::filesystem;

const fs::path kFuzz = HOLEFILL_FUZZ_DIR;

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// The inputs of one target: its seeds, its corpus and its regressions.
std::vector<fs::path> inputs_of(const std::string& target) {
  std::vector<fs::path> inputs;
  for (const char* folder : {"seeds", "corpus"}) {
    if (!fs::is_directory(kFuzz / folder / target)) continue;
    for (const auto& entry : fs::directory_iterator(kFuzz / folder / target)) {
      inputs.push_back(entry.path());
    }
  }
  if (fs::is_directory(kFuzz / "regressions")) {
    for (const auto& entry : fs::directory_iterator(kFuzz / "regressions")) {
      if (entry.path().filename().string().rfind(target + "-", 0) == 0) {
        inputs.push_back(entry.path());
      }
    }
  }
  std::sort(inputs.begin(), inputs.end());
  return inputs;
}

class FuzzCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(FuzzCorpus, EveryInputKeepsEveryPromise) {
  const std::string target = GetParam();
  const auto inputs = inputs_of(target);
  EXPECT_FALSE(inputs.empty()) << "no corpus for " << target;
  for (const auto& input : inputs) {
    const std::string bytes = read_bytes(input);
    std::string problem;
    if (target == "fill") {
      problem = fill_input(bytes);
    } else {
      // load_obj reads files named *.obj, and so on.
      std::string extension = target.substr(target.find('_'));
      extension[0] = '.';
      problem = load_input(bytes, extension);
    }
    EXPECT_EQ(problem, "") << input;
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzCorpus,
                         ::testing::Values("load_obj", "load_off", "load_ply", "load_stl", "fill"));

}  // namespace
}  // namespace holefill::fuzz
