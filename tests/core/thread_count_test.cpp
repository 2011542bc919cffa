// How many threads the library starts, counted where every thread starts (pthread_create,
// thread_counter.h): a count of threads given to loading, preparing, filling and writing bounds
// every stage of them (through the library, `holefill info --threads`, a hole filled alone, the
// viewer's setting), one thread starts none, and the full search asked to choose uses every core
// this process may run on.
#include <gtest/gtest.h>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "holefill/prepare.h"
#include "holefill/triangulate.h"
#include "run_cli.h"
#ifdef HOLEFILL_TEST_VIEWER
#include "session.h"
#endif
#include "test_meshes.h"
#include "thread_counter.h"

namespace holefill::testing {
namespace {

// An OBJ of a wavy n x n grid of squares whose rows of squares were written apart (each row its
// own vertices, so that stitching joins them again: a boundary point per vertex to search
// around), with a hole of 144 edges (more than the full search's threshold for threads) and
// small holes around it. Big enough that every stage that can use threads does: more than 8 MB
// of text, more than 65,536 faces.
std::string rows_apart_obj(int n) {
  const auto removed = [](int i, int j) {
    return (i >= 100 && i < 136 && j >= 100 && j < 136) || (i % 40 == 7 && j % 40 == 7);
  };
  std::string text;
  char line[96];
  for (int j = 0; j < n; ++j) {
    for (int row = j; row <= j + 1; ++row) {
      for (int i = 0; i <= n; ++i) {
        const double x = i / 100.0, y = row / 100.0;
        std::snprintf(line, sizeof line, "v %.9f %.9f %.9f\n", x, y,
                      0.05 * std::sin(3.0 * x) * std::cos(2.0 * y));
        text += line;
      }
    }
  }
  for (int j = 0; j < n; ++j) {
    const int low = 2 * j * (n + 1) + 1, high = low + n + 1;  // the row's two lines of vertices
    for (int i = 0; i < n; ++i) {
      if (removed(i, j)) continue;
      std::snprintf(line, sizeof line, "f %d %d %d\nf %d %d %d\n", low + i, low + i + 1,
                    high + i + 1, low + i, high + i + 1, high + i);
      text += line;
    }
  }
  return text;
}

// Loads, prepares and fills (the holes, not the border) on `threads` threads; the filled mesh as
// an OBJ written on as many.
std::string filled(const std::string& obj, unsigned threads) {
  Mesh mesh = load_mesh_from_memory(obj, "rows.obj", nullptr, threads);
  PrepareOptions preparation;
  preparation.threads = threads;
  const PreparedMesh prepared = prepare_mesh(mesh, preparation);
  FillOptions options;
  options.threads = threads;
  HoleSelection holes;
  holes.max_boundary_edges = 200;  // not the grid's border
  fill_holes(mesh, prepared.holes, options, holes);
  return mesh_to_bytes(mesh, "filled.obj", threads);
}

unsigned cores_of_this_process() {
  cpu_set_t set;
  CPU_ZERO(&set);
  EXPECT_EQ(sched_getaffinity(0, sizeof set, &set), 0);
  return static_cast<unsigned>(CPU_COUNT(&set));
}

TEST(ThreadCount, OneThreadStartsNoThreadInLoadingPreparingFillingOrWriting) {
  const std::string obj = rows_apart_obj(280);
  ASSERT_GT(obj.size(), std::size_t{8} << 20);
  reset_thread_counts();
  const std::string one = filled(obj, 1);
  EXPECT_EQ(thread_counts().started, 0u);
  // The same work on three threads does start some (the count sees them), never more than two
  // beside the caller, and gives the same file.
  reset_thread_counts();
  EXPECT_EQ(filled(obj, 3), one);
  const ThreadCounts three = thread_counts();
  EXPECT_GT(three.started, 0u);
  EXPECT_LE(three.most_at_once, 2u);
  // Stitching joined the rows and the holes were closed: the work was done.
  const Mesh mesh = load_mesh_from_memory(one, "one.obj");
  EXPECT_TRUE(find_holes(mesh).size() == 1u);  // the grid's outer border only
}

TEST(ThreadCount, AHoleFilledAloneIsPlannedOnTheThreadsGiven) {
  // A hole of about 160 edges in a wavy grid.
  const Mesh grid = without_faces(
      make_grid(100,
                [](double x, double y) { return 0.05 * std::sin(3.0 * x) * std::cos(2.0 * y); }),
      [](const Point& c) { return std::abs(c[0] - 0.5) < 0.2 && std::abs(c[1] - 0.5) < 0.2; });
  const auto holes = find_holes(grid);
  const auto hole = std::min_element(
      holes.begin(), holes.end(), [](const Hole& a, const Hole& b) { return a.size() < b.size(); });
  ASSERT_GT(hole->size(), 120u);  // the full search's threshold for threads
  FillOptions options;
  options.last_stage = Stage::Triangulated;
  const auto filled_alone = [&](unsigned threads, bool stepped) {
    options.threads = threads;
    Mesh mesh = grid;
    reset_thread_counts();
    if (stepped) {
      HoleFill fill;
      EXPECT_EQ(advance(mesh, *hole, fill, options), StageRun::Ran);
    } else {
      EXPECT_FALSE(fill_hole(mesh, *hole, options).failed());
    }
    return mesh_to_bytes(mesh, "filled.obj", 1);
  };
  for (const bool stepped : {true, false}) {
    const std::string one = filled_alone(1, stepped);
    EXPECT_EQ(thread_counts().started, 0u) << stepped;
    EXPECT_EQ(filled_alone(2, stepped), one) << stepped;
    EXPECT_LE(thread_counts().most_at_once, 1u) << stepped;
  }
}

TEST(ThreadCount, InfoReadsAndPreparesOnTheThreadsGiven) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("holefill-info-threads-" + std::to_string(getpid()) + ".obj");
  std::ofstream(path, std::ios::binary) << rows_apart_obj(280);
  reset_thread_counts();
  const CliRun one = run_cli({"info", path.string(), "--threads", "1"});
  EXPECT_EQ(thread_counts().started, 0u);
  reset_thread_counts();
  const CliRun three = run_cli({"info", path.string(), "--threads", "3"});
  EXPECT_GT(thread_counts().started, 0u);  // reading halves, stitching's search
  EXPECT_LE(thread_counts().most_at_once, 2u);
  std::filesystem::remove(path);
  EXPECT_EQ(one.code, 0) << one.err;
  EXPECT_EQ(one.out, three.out);
  // 7 x 7 small holes but the one inside the big hole, the big hole, the grid's border.
  EXPECT_NE(one.out.find(" 50 holes\n"), std::string::npos) << one.out;
}

#ifdef HOLEFILL_TEST_VIEWER
TEST(ThreadCount, TheViewersSettingBoundsOpeningFillingAndReplaying) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() /
      ("holefill-viewer-threads-" + std::to_string(getpid()) + ".obj");
  std::ofstream(path, std::ios::binary) << rows_apart_obj(280);
  // Opens, fills every hole but the grid's border, undoes (back to the mesh as loaded) and
  // redoes (every step replayed from it).
  const auto worked = [&](unsigned threads) {
    viewer::Session session;
    session.set_threads(threads);
    reset_thread_counts();
    EXPECT_TRUE(session.open(path)) << session.notice().text;
    EXPECT_TRUE(session.fill_all(200)) << session.notice().text;
    EXPECT_TRUE(session.undo());
    EXPECT_TRUE(session.redo());
    const ThreadCounts counts = thread_counts();  // the session's, not this writing's
    return std::pair{mesh_to_bytes(session.mesh(), "viewer.obj"), counts};
  };
  const auto [one, on_one] = worked(1);
  EXPECT_EQ(on_one.started, 0u);
  const auto [three, on_three] = worked(3);
  std::filesystem::remove(path);
  EXPECT_EQ(three, one);
  EXPECT_GT(on_three.started, 0u);
  EXPECT_LE(on_three.most_at_once, 2u);
  // The holes were closed: the grid's border is the one loop left.
  EXPECT_EQ(find_holes(load_mesh_from_memory(one, "one.obj")).size(), 1u);
}
#endif  // HOLEFILL_TEST_VIEWER

TEST(ThreadCount, TheFullSearchLeftToChooseUsesEveryCoreOfTheProcess) {
  const HolePolygon polygon = wavy_hole(300);
  reset_thread_counts();
  ASSERT_TRUE(triangulate_polygon(polygon, TriangulateOptions{}).has_value());
  // 300 points make 19 strips of rows: more than the cores of most machines.
  EXPECT_EQ(thread_counts().started, std::min(cores_of_this_process(), 19u) - 1);
}

}  // namespace
}  // namespace holefill::testing
