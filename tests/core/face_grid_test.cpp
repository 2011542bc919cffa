// A FaceGrid built on several threads (its cells listed in chunks and merged, merge_on_threads.h)
// finds exactly what a scan of its boxes finds, as one built on one thread does.
#include "face_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "merge_on_threads.h"

namespace holefill::detail {
namespace {

Box box_at(const Point& low, const Point& size) {
  Box box;
  box.add(low);
  box.add(low + size);
  return box;
}

// Many small boxes over [0, 1]^3, a few far larger (filed in no cell), one with a NaN corner.
std::vector<std::pair<int, Box>> many_boxes(int count) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> at(0.0, 1.0), size(0.0, 0.02);
  std::vector<std::pair<int, Box>> boxes;
  for (int id = 0; id < count; ++id) {
    const double scale = id % 997 == 0 ? 40.0 : 1.0;
    boxes.emplace_back(3 * id + 1, box_at(Point(at(rng), at(rng), at(rng)),
                                          scale * Point(size(rng), size(rng), size(rng))));
  }
  boxes[17].second.low[1] = NAN;
  return boxes;
}

std::vector<int> overlapping_by_scan(const std::vector<std::pair<int, Box>>& boxes,
                                     const Box& box) {
  std::vector<int> ids;
  for (const auto& [id, b] : boxes) {
    if (b.overlaps(box)) ids.push_back(id);
  }
  std::sort(ids.begin(), ids.end());
  return ids;
}

TEST(FaceGrid, BuiltOnOneTwoThreeOrMoreThreadsThanChunksFindsWhatAScanFinds) {
  const auto boxes = many_boxes(40000);  // several chunks of entries
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> at(-0.1, 1.0), size(0.0, 0.2);
  std::vector<Box> lookups{box_at(Point(-1, -1, -1), Point(3, 3, 3))};
  for (int l = 0; l < 60; ++l) {
    lookups.push_back(box_at(Point(at(rng), at(rng), at(rng)), Point(size(rng), size(rng), 0.05)));
  }
  for (const unsigned threads : {1u, 2u, 3u, 1000u}) {
    const FaceGrid grid(boxes, threads);
    std::size_t found = 0;
    for (const Box& box : lookups) {
      const auto near = grid.near(box);
      found += near.size();
      ASSERT_EQ(near, overlapping_by_scan(boxes, box)) << threads << " threads";
    }
    EXPECT_GT(found, 40000u);
  }
}

// An element ordered by its value alone, and its run, which a tie must keep in the runs' order.
struct Tagged {
  int value, run;
  bool operator<(const Tagged& other) const { return value < other.value; }
  bool operator==(const Tagged&) const = default;
};

// Runs of several lengths (an empty one too) with ties inside and across runs, merged on 1, 2, 3
// and more threads than elements: the stable sort of the runs one after another (std::merge's
// order, ties taken from the earlier run).
TEST(MergeOnThreads, MergesAsAStableSortOnAnyThreads) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> value(0, 50);
  for (const int runs : {1, 2, 3, 5}) {
    std::vector<std::vector<Tagged>> input(static_cast<std::size_t>(runs));
    std::vector<Tagged> all;
    for (int r = 0; r < runs; ++r) {
      auto& run = input[static_cast<std::size_t>(r)];
      for (int i = 0; i < (r == 1 ? 0 : 7 + 31 * r); ++i) run.push_back({value(rng), r});
      std::sort(run.begin(), run.end());
      all.insert(all.end(), run.begin(), run.end());
    }
    std::stable_sort(all.begin(), all.end());
    for (const unsigned threads : {1u, 2u, 3u, 1000u}) {
      EXPECT_EQ(merge_runs(input, threads), all) << runs << " runs, " << threads << " threads";
    }
  }
}

}  // namespace
}  // namespace holefill::detail
