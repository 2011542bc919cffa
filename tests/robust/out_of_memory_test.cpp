// Running out of memory: a clear message, its own exit code, no output, wherever it happens.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <thread>

#include "failing_allocator.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/progress.h"
#include "robust_test_util.h"
#include "test_meshes.h"

namespace holefill {
namespace {
namespace fs = std::filesystem;
using testing::ScratchTest;

constexpr int kCaughtBadAlloc = 42;

// Out of memory in a worker thread ended the process through std::terminate (exit 134).
TEST(OutOfMemory, InAWorkerThreadReachesTheCallerWithTheMeshUnchanged) {
  if (std::thread::hardware_concurrency() < 2) {
    GTEST_SKIP() << "one core: fill_holes runs every hole on the calling thread";
  }
  Mesh mesh = testing::grid_with_square_holes(30);
  const auto holes = find_holes(mesh);
  ASSERT_GE(holes.size(), 50u);
  const std::size_t faces = mesh.n_faces();
  // This thread plans holes too: left alone on a busy machine it could plan them all before the
  // other thread ran. Its first report waits (up to 20 s) until an allocation off it has failed.
  Progress wait_for_a_worker([main = std::this_thread::get_id()](double) {
    for (int waited = 0; std::this_thread::get_id() == main && testing::failed_allocations() == 0 &&
                         waited < 20'000;
         ++waited) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  });
  EXPECT_EXIT(
      {
        testing::fail_allocations_off_this_thread();
        try {
          fill_holes(mesh, holes, FillOptions{}, {}, &wait_for_a_worker);
        } catch (const std::bad_alloc&) {
          testing::stop_failing_allocations();
          std::_Exit(mesh.n_faces() == faces ? kCaughtBadAlloc : 1);
        }
        std::_Exit(0);
      },
      ::testing::ExitedWithCode(kCaughtBadAlloc), "");
}

// A large hole's dynamic program on several threads: its helper threads, which nothing there
// could catch a failure on, allocate nothing (an allocation there ended the process in
// std::terminate when the machine was idle enough to give a hole's program a second thread).
TEST(OutOfMemory, TheDynamicProgramsHelperThreadsAllocateNothing) {
  const Mesh grid = testing::make_grid(41, [](double, double) { return 0.0; });
  Mesh mesh = testing::without_faces(grid, [](const Point& centroid) {
    return std::abs(centroid[0] - 0.5) < 0.25 && std::abs(centroid[1] - 0.5) < 0.25;
  });
  const auto holes = find_holes(mesh);
  const auto inner = std::min_element(holes.begin(), holes.end(), [](const Hole& a, const Hole& b) {
    return a.halfedges.size() < b.halfedges.size();
  });
  ASSERT_GE(inner->halfedges.size(), 64u);  // rows for several strips, one per thread
  FillOptions options;
  options.triangulate.threads = 4;
  const std::size_t faces = mesh.n_faces();
  EXPECT_EXIT(
      {
        testing::fail_allocations_off_this_thread();
        const HoleFill fill = fill_hole(mesh, *inner, options);
        testing::stop_failing_allocations();
        std::_Exit(!fill.failed() && mesh.n_faces() > faces ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

using OutOfMemoryCli = ScratchTest;

// Out of memory was reported as "bad input" (exit 3).
TEST_F(OutOfMemoryCli, HasItsOwnExitCodeAndWritesNothing) {
  const std::string bunny = (fs::path(HOLEFILL_ASSETS_DIR) / "bunny.obj").string();
  const std::string out = path("out.obj");
  EXPECT_EXIT(
      {
        testing::fail_allocations_larger_than(std::size_t{1} << 16);  // the file is larger
        std::exit(cli::run({"fill", bunny, "-o", out}, std::cout, std::cerr));
      },
      ::testing::ExitedWithCode(cli::kOutOfMemory), "holefill: out of memory");
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace holefill
