// The full search's table budget (table_budget.h): how much concurrent searches may hold.
#include "table_budget.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "full_search.h"
#include "holefill/triangulate.h"
#include "test_meshes.h"

namespace holefill {
namespace {

using detail::TableBudget;

TEST(TableBudget, HoldsNoMoreThanTheBudgetAtOnce) {
  TableBudget budget(100);
  std::atomic<int> granted{0};
  std::atomic<std::size_t> held{0}, most_held{0};
  {
    std::vector<std::jthread> threads;
    for (int t = 0; t < 8; ++t) {
      threads.emplace_back([&] {
        for (int round = 0; round < 20; ++round) {
          const TableBudget::Lease lease = budget.acquire(40);
          ASSERT_TRUE(lease.held());
          const std::size_t now = held += 40;
          std::size_t most = most_held.load();
          while (now > most && !most_held.compare_exchange_weak(most, now)) {
          }
          std::this_thread::sleep_for(std::chrono::microseconds(300));
          held -= 40;
          ++granted;
        }
      });
    }
  }
  EXPECT_EQ(granted, 160);
  EXPECT_LE(most_held, 80u);  // two leases of 40 fit in 100, three do not
  EXPECT_LE(budget.peak_held(), 80u);
}

TEST(TableBudget, LetsALoneSearchExceedIt) {
  TableBudget budget(10);
  const TableBudget::Lease lease = budget.acquire(50);
  EXPECT_TRUE(lease.held());
  EXPECT_EQ(budget.peak_held(), 50u);
}

TEST(TableBudget, AWaitingSearchRunsOnceRoomIsFreedOrGivesUpWhenAsked) {
  TableBudget budget(100);
  auto first = std::make_unique<TableBudget::Lease>(budget.acquire(80));
  int asked = 0;
  const TableBudget::Lease abandoned = budget.acquire(40, [&] { return ++asked >= 3; });
  EXPECT_FALSE(abandoned.held());
  EXPECT_EQ(asked, 3);

  std::atomic<bool> got{false};
  std::jthread waiter([&] {
    const TableBudget::Lease lease = budget.acquire(40);
    got = lease.held();
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_FALSE(got);  // 80 + 40 > 100: still waiting
  first.reset();
  waiter.join();
  EXPECT_TRUE(got);
  EXPECT_EQ(budget.peak_held(), 80u);
}

// Four full searches at once under a budget that fits two: they take turns, and each finds the
// triangulation it finds alone.
TEST(TableBudget, FullSearchesRunningAtOnceShareIt) {
  TableBudget& budget = detail::full_search_table_budget();
  const std::size_t before = budget.budget();
  const std::size_t one = detail::table_bytes(300, true);
  TriangulateOptions options;
  options.threads = 1;
  options.restricted.above_edges = 0;
  std::vector<HolePolygon> holes;
  std::vector<std::vector<std::array<int, 3>>> alone;
  for (int h = 0; h < 4; ++h) {
    holes.push_back(testing::wavy_hole(300 - h));
    alone.push_back(triangulate_polygon(holes.back(), options)->triangles);
  }
  budget.set_budget(2 * one);
  std::vector<std::vector<std::array<int, 3>>> together(4);
  {
    std::vector<std::jthread> threads;
    for (int h = 0; h < 4; ++h) {
      threads.emplace_back(
          [&, h] { together[h] = triangulate_polygon(holes[h], options)->triangles; });
    }
  }
  const std::size_t peak = budget.peak_held();
  budget.set_budget(before);
  EXPECT_LE(peak, 2 * one);
  EXPECT_GT(peak, 0u);  // the searches drew on it
  EXPECT_EQ(together, alone);
}

}  // namespace
}  // namespace holefill
