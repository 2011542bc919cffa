// Running out of memory: a clear message, its own exit code, no output, wherever it happens.
#include <iostream>
#include <thread>

#include "failing_allocator.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
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
  EXPECT_EXIT(
      {
        testing::fail_allocations_off_this_thread();
        try {
          fill_holes(mesh, holes, FillOptions{});
        } catch (const std::bad_alloc&) {
          testing::stop_failing_allocations();
          std::_Exit(mesh.n_faces() == faces ? kCaughtBadAlloc : 1);
        }
        std::_Exit(0);
      },
      ::testing::ExitedWithCode(kCaughtBadAlloc), "");
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
