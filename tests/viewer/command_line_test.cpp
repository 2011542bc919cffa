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
  EXPECT_TRUE(parse_command_line({"--help"}).help);
}

TEST(CommandLine, TheBundledBunnyIsFound) {
  EXPECT_TRUE(std::filesystem::exists(default_mesh_path("/nowhere/holefill-viewer")));
}

}  // namespace
}  // namespace holefill::viewer
