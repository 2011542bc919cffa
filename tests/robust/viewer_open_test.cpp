// The viewer with bad input: opening any file that load_mesh refuses leaves the mesh
// that was open, its holes and its fill steps as they were, and the notice names the file and
// the problem. The session is the viewer's logic without a window.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "session.h"

namespace holefill::viewer {
namespace {
namespace fs = std::filesystem;

TEST(ViewerOpen, ABadFileShowsWhyAndKeepsThePreviousMesh) {
  // Per process: two test runs on one machine must not share it.
  const fs::path dir =
      fs::temp_directory_path() / ("holefill_robust_viewer_open_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "folder.obj");
  auto write = [&dir](const std::string& name, const std::string& bytes) {
    std::ofstream(dir / name, std::ios::binary) << bytes;
    return dir / name;
  };
  const std::vector<std::pair<fs::path, std::string>> bad{
      {write("empty.obj", ""), "is empty"},
      {write("garbage.ply", std::string("\x01\x02garbage\0\xff", 12)), "does not start with"},
      {write("huge.off", "OFF\n99999999999 1 0\n"), "the header promises"},
      {write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"), "non-finite"},
      {write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n"), "refers to vertex 7"},
      {write("points.xyz", "1 2 3\n"), "unsupported"},
      {dir / "folder.obj", "is a directory"},
      {dir / "missing.stl", "no such file"},
  };
  Session session;
  ASSERT_TRUE(session.open(fs::path(HOLEFILL_ASSETS_DIR) / "bunny.obj")) << session.notice().text;
  session.select(0);
  ASSERT_TRUE(session.fill_selected());
  const Mesh filled = session.mesh();
  const std::string name = session.name();
  const auto steps = session.log().size();
  for (const auto& [file, reason] : bad) {
    EXPECT_FALSE(session.open(file)) << file;
    EXPECT_TRUE(session.notice().error);
    EXPECT_NE(session.notice().text.find(file.string()), std::string::npos)
        << session.notice().text;
    EXPECT_NE(session.notice().text.find(reason), std::string::npos) << session.notice().text;
    EXPECT_EQ(session.name(), name);
    EXPECT_EQ(session.log().size(), steps);
    EXPECT_EQ(session.mesh().n_faces(), filled.n_faces());
    EXPECT_EQ(session.holes().size(), 3u);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace holefill::viewer
