#include "box_buckets.h"

#include <algorithm>
#include <cmath>

namespace holefill::detail {
namespace {

// A box filed under more cells than this goes to the list every lookup tests; a lookup over more
// than kMaxLookupCells tests every box instead of its cells.
constexpr double kMaxBucketsPerBox = 64, kMaxLookupCells = 4096;
// Cell indices are clamped to this range, so that they fit in 64 bits whatever the coordinates.
constexpr double kMaxBucketIndex = 1e15;
// The cell size taken from the first box, in multiples of its extent.
constexpr double kCellsOfFirstBox = 4.0;

// 21 bits per axis; distant cells may share a key, which only adds candidates. Below 2^63: never
// the hash map's empty key.
std::uint64_t bucket_key(std::int64_t x, std::int64_t y, std::int64_t z) {
  auto bits = [](std::int64_t i) { return static_cast<std::uint64_t>(i) & 0x1FFFFF; };
  return bits(x) << 42 | bits(y) << 21 | bits(z);
}

bool usable_cell(double cell) { return std::isfinite(cell) && cell > 0.0; }

}  // namespace

BoxBuckets::BoxBuckets(double cell) : cell_(usable_cell(cell) ? cell : 0.0) {}

bool BoxBuckets::span_of(const Box& box, CellSpan& span) const {
  span.count = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double low = std::floor(box.low[axis] / cell_), high = std::floor(box.high[axis] / cell_);
    if (std::isnan(low) || std::isnan(high)) return false;
    span.low[axis] = static_cast<std::int64_t>(std::clamp(low, -kMaxBucketIndex, kMaxBucketIndex));
    span.high[axis] =
        static_cast<std::int64_t>(std::clamp(high, -kMaxBucketIndex, kMaxBucketIndex));
    span.count *= static_cast<double>(span.high[axis] - span.low[axis] + 1);
  }
  return true;
}

void BoxBuckets::add(int id, const Box& box) {
  if (cell_ == 0.0) {
    const double cell = kCellsOfFirstBox * (box.high - box.low).max();
    if (usable_cell(cell)) cell_ = cell;
  }
  const int entry = static_cast<int>(entries_.size());
  entries_.emplace_back(id, box);
  // Cell indices grow with the coordinates (clamped, infinities too), so boxes that overlap share
  // a cell; a NaN coordinate has no cell.
  CellSpan span;
  if (cell_ == 0.0 || !span_of(box, span) || !(span.count <= kMaxBucketsPerBox)) {
    wide_.push_back(entry);
    return;
  }
  for (auto x = span.low[0]; x <= span.high[0]; ++x) {
    for (auto y = span.low[1]; y <= span.high[1]; ++y) {
      for (auto z = span.low[2]; z <= span.high[2]; ++z) {
        int& first = first_link_.find_or_insert(bucket_key(x, y, z), kNoLink);
        links_.push_back({entry, first});
        first = static_cast<int>(links_.size()) - 1;
      }
    }
  }
}

std::size_t BoxBuckets::append_overlapping(const Box& box, std::vector<int>& ids) const {
  const std::size_t before = ids.size();
  auto test = [&](int entry) {
    const auto& [id, entry_box] = entries_[static_cast<std::size_t>(entry)];
    if (entry_box.overlaps(box)) ids.push_back(id);
  };
  CellSpan span;
  if (cell_ == 0.0 || !span_of(box, span) || !(span.count <= kMaxLookupCells)) {
    for (int entry = 0; entry < static_cast<int>(entries_.size()); ++entry) test(entry);
    return ids.size() - before;
  }
  // An entry filed under several of the lookup's cells is tested once.
  std::vector<int> tested;
  for (auto x = span.low[0]; x <= span.high[0]; ++x) {
    for (auto y = span.low[1]; y <= span.high[1]; ++y) {
      for (auto z = span.low[2]; z <= span.high[2]; ++z) {
        for (int link = first_link_.find(bucket_key(x, y, z), kNoLink); link != kNoLink;
             link = links_[static_cast<std::size_t>(link)].next) {
          tested.push_back(links_[static_cast<std::size_t>(link)].entry);
        }
      }
    }
  }
  std::sort(tested.begin(), tested.end());
  tested.erase(std::unique(tested.begin(), tested.end()), tested.end());
  for (const int entry : tested) test(entry);
  for (const int entry : wide_) test(entry);
  return ids.size() - before;
}

}  // namespace holefill::detail
