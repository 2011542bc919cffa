// BoxBuckets and FaceGrid against a scan of every box: the same ids for lookups of every size and
// for boxes with huge, infinite, NaN or no extent, whatever the cell size.
#include "box_buckets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "face_grid.h"

namespace holefill::detail {
namespace {

Box box_between(const Point& a, const Point& b) {
  Box box;
  box.add(a);
  box.add(b);
  return box;
}

std::vector<int> sorted_overlapping(const BoxBuckets& buckets, const Box& box) {
  std::vector<int> ids{-7};  // what was there before stays, first
  const std::size_t appended = buckets.append_overlapping(box, ids);
  EXPECT_EQ(ids.front(), -7);
  EXPECT_EQ(appended, ids.size() - 1);
  ids.erase(ids.begin());
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::vector<int> scanned_overlapping(const std::vector<std::pair<int, Box>>& added,
                                     const Box& box) {
  std::vector<int> ids;
  for (const auto& [id, entry] : added) {
    if (entry.overlaps(box)) ids.push_back(id);
  }
  std::sort(ids.begin(), ids.end());
  return ids;
}

// Small boxes in [0, 10]^3 as patches' faces are, and a few odd ones among them.
Box random_box(std::mt19937& rng, int kind) {
  std::uniform_real_distribution<double> at(-1.0, 11.0), size(0.0, 0.4);
  const Point low(at(rng), at(rng), at(rng));
  switch (kind) {
    case 0:
      return box_between(low, low + Point(50.0, 0.1, 0.1));  // long: spans many cells
    case 1:
      return box_between(low, low);  // a point
    case 2:
      return box_between(low, Point(INFINITY, low[1] + 0.1, low[2] + 0.1));
    case 3:
      return box_between(Point(NAN, low[1], low[2]), low);
    case 4:
      return Box{};  // empty
    case 5:
      return box_between(low * 1e300, (low + Point(0.1, 0.1, 0.1)) * 1e300);
    default:
      return box_between(low, low + Point(size(rng), size(rng), size(rng)));
  }
}

TEST(BoxBuckets, FindsWhatAScanOfEveryBoxFinds) {
  for (const double cell : {0.0, 1e-3, 0.5, 3.0, 1e9, double{NAN}}) {
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> kind(0, 60);
    BoxBuckets buckets(cell);
    std::vector<std::pair<int, Box>> added;
    for (int round = 0; round < 3000; ++round) {
      const Box box = random_box(rng, kind(rng));
      added.emplace_back(round * 3, box);  // ids need not be indices
      buckets.add(added.back().first, box);
      if (round % 10 == 0) {
        // Lookups of a patch's size, larger ones, and the odd boxes above.
        const int lookup_kind = kind(rng);
        Box lookup = random_box(rng, lookup_kind);
        if (round % 20 == 0) lookup.grow(2.0);
        ASSERT_EQ(sorted_overlapping(buckets, lookup), scanned_overlapping(added, lookup))
            << "cell " << cell << ", round " << round << ", kind " << lookup_kind;
      }
    }
    EXPECT_EQ(buckets.size(), added.size());
    const Box everything =
        box_between(Point(-INFINITY, -INFINITY, -INFINITY), Point(INFINITY, INFINITY, INFINITY));
    EXPECT_EQ(sorted_overlapping(buckets, everything), scanned_overlapping(added, everything));
  }
}

TEST(FaceGrid, FindsWhatAScanOfEveryBoxFinds) {
  std::uniform_int_distribution<int> kind(0, 60);
  for (const int count : {0, 1, 7, 3000}) {
    for (const double scale : {1.0, 1e-200, 1e200}) {
      std::mt19937 rng(count);
      std::vector<std::pair<int, Box>> boxes;
      for (int b = 0; b < count; ++b) {
        Box box = random_box(rng, kind(rng));
        box.low *= scale;
        box.high *= scale;
        boxes.emplace_back(5 * b + 3, box);  // ids need not be indices
      }
      const FaceGrid grid(boxes);
      for (int lookup = 0; lookup < 300; ++lookup) {
        const int lookup_kind = kind(rng);
        Box box = random_box(rng, lookup_kind);
        if (lookup % 2 == 0) box.grow(2.0);
        box.low *= scale;
        box.high *= scale;
        // near() promises ascending ids, each once: what the sorted scan gives.
        ASSERT_EQ(grid.near(box), scanned_overlapping(boxes, box))
            << count << " boxes, scale " << scale << ", lookup " << lookup << ", kind "
            << lookup_kind;
      }
    }
  }
}

}  // namespace
}  // namespace holefill::detail
