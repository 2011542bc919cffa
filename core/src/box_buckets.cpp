#include "box_buckets.h"

#include <algorithm>
#include <cmath>

namespace holefill::detail {
namespace {

// A box filed under more cells than this goes to the list every lookup tests; a lookup over more
// than kMaxLookupCells tests every box instead of its cells.
constexpr double kMaxBucketsPerBox = 64, kMaxLookupCells = 4096;
// The cell size taken from the first box, in multiples of its extent.
constexpr double kCellsOfFirstBox = 4.0;

bool usable_cell(double cell) { return std::isfinite(cell) && cell > 0.0; }

}  // namespace

BoxBuckets::BoxBuckets(double cell) : cell_(usable_cell(cell) ? cell : 0.0) {}

void BoxBuckets::add(int id, const Box& box) {
  if (cell_ == 0.0) {
    const double cell = kCellsOfFirstBox * (box.high - box.low).max();
    if (usable_cell(cell)) cell_ = cell;
  }
  const int entry = static_cast<int>(entries_.size());
  entries_.emplace_back(id, box);
  // Boxes that overlap share a cell (cell_span); a NaN coordinate has no cell.
  const auto span = cell_ == 0.0 ? std::nullopt : cell_span(box, cell_);
  if (!span || !(span->count <= kMaxBucketsPerBox)) {
    wide_.push_back(entry);
    return;
  }
  for_each_cell_key(*span, [&](std::uint64_t key) {
    int& first = first_link_.find_or_insert(key, kNoLink);
    links_.push_back({entry, first});
    first = static_cast<int>(links_.size()) - 1;
  });
}

std::size_t BoxBuckets::append_overlapping(const Box& box, std::vector<int>& ids) const {
  const std::size_t before = ids.size();
  auto test = [&](int entry) {
    const auto& [id, entry_box] = entries_[static_cast<std::size_t>(entry)];
    if (entry_box.overlaps(box)) ids.push_back(id);
  };
  const auto span = cell_ == 0.0 ? std::nullopt : cell_span(box, cell_);
  if (!span || !(span->count <= kMaxLookupCells)) {
    for (int entry = 0; entry < static_cast<int>(entries_.size()); ++entry) test(entry);
    return ids.size() - before;
  }
  // An entry filed under several of the lookup's cells is tested once.
  std::vector<int> tested;
  for_each_cell_key(*span, [&](std::uint64_t key) {
    for (int link = first_link_.find(key, kNoLink); link != kNoLink;
         link = links_[static_cast<std::size_t>(link)].next) {
      tested.push_back(links_[static_cast<std::size_t>(link)].entry);
    }
  });
  std::sort(tested.begin(), tested.end());
  tested.erase(std::unique(tested.begin(), tested.end()), tested.end());
  for (const int entry : tested) test(entry);
  for (const int entry : wide_) test(entry);
  return ids.size() - before;
}

}  // namespace holefill::detail
