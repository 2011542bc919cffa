#include "command_line.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace holefill::viewer {
namespace {

TEST(CommandLine, ScriptedModeOptions) {
  const CommandLine c = parse_command_line({"mesh.ply", "--select-hole", "2", "--run",
                                            "triangulate,refine", "--compare-triangulation-only",
                                            "--size", "640x480", "--screenshot", "out.png"});
  EXPECT_EQ(c.mesh, "mesh.ply");
  EXPECT_EQ(c.select_hole, 2);
  ASSERT_EQ(c.run.size(), 2u);
  EXPECT_EQ(c.run[1], Stage::Refined);
  EXPECT_TRUE(c.compare);
  EXPECT_TRUE(c.compare_triangulation_only);
  EXPECT_EQ(c.width, 640);
  EXPECT_EQ(c.height, 480);
  EXPECT_EQ(c.screenshot, "out.png");
  EXPECT_FALSE(c.remesh || c.fair);
  const CommandLine quality = parse_command_line({"--remesh", "--fair"});
  EXPECT_TRUE(quality.remesh && quality.fair);
  EXPECT_EQ(quality.fair_order, 2);
  EXPECT_EQ(parse_command_line({"--fair-order", "3"}).fair_order, 3);
  EXPECT_FLOAT_EQ(parse_command_line({}).ui_scale, 0.0f);  // the monitor's
  EXPECT_FLOAT_EQ(parse_command_line({"--ui-scale", "1.5"}).ui_scale, 1.5f);
  EXPECT_EQ(parse_command_line({}).threads, 0u);  // every core
  EXPECT_EQ(parse_command_line({"--threads", "3"}).threads, 3u);
  const CommandLine smoothing = parse_command_line({"--select-hole", "0", "--compare-smoothing"});
  EXPECT_TRUE(smoothing.compare && smoothing.compare_smoothing);
}

TEST(CommandLine, RejectsWhatItCannotDo) {
  EXPECT_THROW(parse_command_line({"--run", "triangulate"}), std::invalid_argument);
  EXPECT_THROW(parse_command_line({"--select-hole", "1", "--run", "fair"}), std::invalid_argument);
  EXPECT_THROW(parse_command_line({"--size", "big"}), std::invalid_argument);
  EXPECT_THROW(parse_command_line({"--select-hole"}), std::invalid_argument);
  EXPECT_THROW(parse_command_line({"a.obj", "b.obj"}), std::invalid_argument);
  EXPECT_THROW(parse_command_line({"--bogus"}), std::invalid_argument);
  EXPECT_THROW(parse_command_line({"--fair-order", "4"}), std::invalid_argument);
  EXPECT_THROW(parse_command_line({"--ui-scale", "9"}), std::invalid_argument);
  EXPECT_THROW(parse_command_line({"--threads", "-1"}), std::invalid_argument);
  EXPECT_TRUE(parse_command_line({"--help"}).help);
}

// Found from the executable's place, nothing compiled in: this test sits in build/tests/viewer,
// as the viewer sits in build/app/viewer; an installed viewer looks in ../share/holefill.
TEST(CommandLine, TheBundledBunnyIsFoundFromTheExecutable) {
  const auto self = std::filesystem::read_symlink("/proc/self/exe");
  const auto bunny = default_mesh_path(self);
  EXPECT_TRUE(std::filesystem::exists(bunny)) << bunny;
  EXPECT_EQ(bunny.filename(), "bunny.obj");
  EXPECT_FALSE(std::filesystem::exists(default_mesh_path("/nowhere/bin/holefill-viewer")));
  const std::filesystem::path prefix = std::filesystem::temp_directory_path() / "holefill-prefix";
  std::filesystem::create_directories(prefix / "bin");
  std::filesystem::create_directories(prefix / "share/holefill/assets");
  std::filesystem::copy_file(bunny, prefix / "share/holefill/assets/bunny.obj",
                             std::filesystem::copy_options::overwrite_existing);
  EXPECT_EQ(default_mesh_path(prefix / "bin/holefill-viewer"),
            prefix / "share/holefill/assets/bunny.obj");
  std::filesystem::remove_all(prefix);
}

// The conventions CLI11 gives: --opt=value, --version, and the defaults in the help.
TEST(CommandLine, TakesTheUsualForms) {
  const CommandLine c = parse_command_line({"--select-hole=1", "--size=800x600", "--", "-odd.obj"});
  EXPECT_EQ(c.select_hole, 1);
  EXPECT_EQ(c.width, 800);
  EXPECT_EQ(c.mesh, "-odd.obj");
  EXPECT_TRUE(parse_command_line({"--version"}).version);
  EXPECT_NE(usage().find("1280x800"), std::string::npos) << usage();
  EXPECT_NE(usage().find("--fair-order"), std::string::npos);
  EXPECT_EQ(parse_command_line({"--frames", "8", "--screenshot", "a.png"}).report_frame_time, true);
  EXPECT_TRUE(parse_command_line({"--select-hole", "0", "--compare-smoothing"}).compare);
}

}  // namespace
}  // namespace holefill::viewer
