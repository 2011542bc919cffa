// Shared by the robustness suites: a scratch folder per test, writing bytes, running the CLI.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "holefill/errors.h"
#include "holefill/io.h"
#include "run_cli.h"

namespace holefill::testing {

// Vertices and faces as a file lists them, before any repair.
struct Soup {
  std::vector<Point> points;
  std::vector<std::vector<int>> faces;
};

inline Soup soup_of(const Mesh& mesh) {
  Soup soup;
  for (const auto v : mesh.vertices()) soup.points.push_back(mesh.point(v));
  for (const auto f : mesh.faces()) {
    soup.faces.emplace_back();
    for (const auto v : mesh.fv_range(f)) soup.faces.back().push_back(v.idx());
  }
  return soup;
}

inline std::string obj_text(const std::vector<Point>& points,
                            const std::vector<std::vector<int>>& faces) {
  std::ostringstream text;
  text.precision(17);
  for (const auto& p : points) text << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for (const auto& f : faces) {
    text << 'f';
    for (const int c : f) text << ' ' << c + 1;
    text << '\n';
  }
  return text.str();
}

inline std::string obj_text(const Soup& soup) { return obj_text(soup.points, soup.faces); }

// The whole contents of a file ("" when it cannot be read).
inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The reason load_mesh_from_memory refuses `bytes` with, or "" when it reads them.
inline std::string refusal(const std::string& bytes, const std::string& name) {
  try {
    load_mesh_from_memory(bytes, name);
  } catch (const FileError& e) {
    return e.reason();
  }
  return "";
}

class ScratchTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("holefill_robust_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
            std::to_string(::getpid()));  // two test runs on one machine must not share it
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::permissions(dir_, std::filesystem::perms::all,
                                 std::filesystem::perm_options::add, ec);
    std::filesystem::remove_all(dir_, ec);
  }
  std::filesystem::path write(const std::string& name, const std::string& bytes) const {
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
    return dir_ / name;
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::filesystem::path dir_;
};

// Whether one of the load's warnings contains `part`.
inline bool has_warning(const LoadReport& report, const std::string& part) {
  for (const auto& warning : report.warnings) {
    if (warning.find(part) != std::string::npos) return true;
  }
  return false;
}

}  // namespace holefill::testing
