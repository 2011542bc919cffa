// What the CLI tests share: a fresh temporary folder per test, reading a file back.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_cli.h"

namespace holefill::testing {

namespace fs = std::filesystem;

inline const fs::path kAssets = HOLEFILL_ASSETS_DIR;
inline std::string bunny() { return (kAssets / "bunny.obj").string(); }

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("holefill_cli_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(::getpid()));  // two test runs on one machine must not share it
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string in_dir(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

inline std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace holefill::testing
