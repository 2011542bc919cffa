#include "face_grid.h"

#include <algorithm>
#include <cmath>

#include "merge_on_threads.h"
#include "parallel_indices.h"

namespace holefill::detail {
namespace {

// A face filed under more cells than this, or a lookup over more, goes through the list instead.
constexpr double kMaxCellsPerFace = 64, kMaxCellsPerLookup = 1 << 20;
// Cell indices are clamped to this range, so that they fit in 64 bits whatever the coordinates.
constexpr double kMaxCellIndex = 1e15;
// Entries below this many per thread are filed on fewer threads: starting one costs more.
constexpr std::size_t kEntriesPerChunk = 8192;

}  // namespace

std::optional<CellSpan> cell_span(const Box& box, double cell) {
  CellSpan span;
  span.count = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double low = std::floor(box.low[axis] / cell), high = std::floor(box.high[axis] / cell);
    if (std::isnan(low) || std::isnan(high)) return std::nullopt;
    span.low[axis] = static_cast<std::int64_t>(std::clamp(low, -kMaxCellIndex, kMaxCellIndex));
    span.high[axis] = static_cast<std::int64_t>(std::clamp(high, -kMaxCellIndex, kMaxCellIndex));
    span.count *= static_cast<double>(span.high[axis] - span.low[axis] + 1);
  }
  return span;
}

std::uint64_t cell_key(std::int64_t x, std::int64_t y, std::int64_t z) {
  auto bits = [](std::int64_t i) { return static_cast<std::uint64_t>(i) & 0x1FFFFF; };
  return bits(x) << 42 | bits(y) << 21 | bits(z);
}

double Box::magnitude() const {
  double largest = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    largest = std::max({largest, std::abs(low[axis]), std::abs(high[axis])});
  }
  return low[0] <= high[0] ? largest : 0.0;
}

Box box_of(const Mesh& mesh, FaceHandle face) {
  Box box;
  for (const auto v : mesh.fv_range(face)) box.add(mesh.point(v));
  return box;
}

FaceGrid::FaceGrid(std::vector<std::pair<int, Box>> boxes, unsigned threads)
    : entries_(std::move(boxes)) {
  // The mean extent, accumulated so that it cannot overflow; infinite extents are left out.
  double mean_extent = 0.0;
  std::size_t counted = 0;
  for (const auto& [id, box] : entries_) {
    const double extent = (box.high - box.low).max();
    if (!std::isfinite(extent)) continue;
    mean_extent += (extent - mean_extent) / static_cast<double>(++counted);
  }
  const double cell = 2.0 * mean_extent;
  cell_ = std::isfinite(cell) && cell > 0.0 ? cell : 1.0;
  // The entries in consecutive chunks, one per thread: each chunk's cells listed and sorted on
  // its thread, the sorted runs merged (the same array on any number of threads: no two pairs
  // are equal), the chunks' unfiled entries joined in order.
  const std::size_t count = entries_.size();
  const std::size_t chunks =
      threads < 2 ? 1 : std::clamp<std::size_t>(count / kEntriesPerChunk, 1, threads);
  std::vector<std::vector<std::pair<std::uint64_t, std::size_t>>> runs(chunks);
  std::vector<std::vector<std::size_t>> unfiled(chunks);
  for_each_index(chunks, threads, [&](std::size_t chunk) {
    auto& run = runs[chunk];
    for (std::size_t e = count * chunk / chunks; e < count * (chunk + 1) / chunks; ++e) {
      const auto range = cell_span(entries_[e].second, cell_);
      if (!range || !(range->count <= kMaxCellsPerFace)) {
        unfiled[chunk].push_back(e);
        continue;
      }
      for_each_cell_key(*range, [&](std::uint64_t key) { run.emplace_back(key, e); });
    }
    std::sort(run.begin(), run.end());
  });
  for (const auto& chunk : unfiled) unfiled_.insert(unfiled_.end(), chunk.begin(), chunk.end());
  cells_ = merge_runs(std::move(runs), threads);
}

std::vector<int> FaceGrid::near(const Box& box) const {
  std::vector<std::size_t> found;
  const auto range = cell_span(box, cell_);
  if (!range || !(range->count <= kMaxCellsPerLookup)) {
    for (std::size_t e = 0; e < entries_.size(); ++e) found.push_back(e);
  } else {
    // A column of cells along z has consecutive keys unless the z index wraps in the key's 21
    // bits: one binary search finds the whole column's entries instead of one per cell (lookups
    // were 13 % of filling 20,000 holes; this took a seventh off them: bench/NOTEBOOK.md).
    const auto& low = range->low;
    const auto& high = range->high;
    const auto column_from = [&](std::uint64_t first, std::uint64_t last) {
      auto at = std::lower_bound(cells_.begin(), cells_.end(),
                                 std::pair<std::uint64_t, std::size_t>(first, 0));
      for (; at != cells_.end() && at->first <= last; ++at) found.push_back(at->second);
    };
    for (auto x = low[0]; x <= high[0]; ++x) {
      for (auto y = low[1]; y <= high[1]; ++y) {
        const std::uint64_t first = cell_key(x, y, low[2]), last = cell_key(x, y, high[2]);
        if (last >= first && last - first == static_cast<std::uint64_t>(high[2] - low[2])) {
          column_from(first, last);
        } else {
          for (auto z = low[2]; z <= high[2]; ++z)
            column_from(cell_key(x, y, z), cell_key(x, y, z));
        }
      }
    }
    found.insert(found.end(), unfiled_.begin(), unfiled_.end());
  }
  std::vector<int> ids;
  for (const std::size_t e : found) {
    if (entries_[e].second.overlaps(box)) ids.push_back(entries_[e].first);
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

}  // namespace holefill::detail
