// Sorted runs merged on several threads (FaceGrid's cell lists, face_grid.h): the runs are merged
// pairwise, round after round, and each merge is cut at fixed ranks into one piece per thread,
// each piece merged on its own (the split found by binary search, as std::merge would take the
// elements: from the first run on ties). The result is std::merge's, so whatever the number of
// threads it is the same array; with distinct elements it is the one std::sort gives.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "parallel_indices.h"

namespace holefill::detail {

// How many of the first `rank` elements of std::merge(a, b) come from a.
template <class T>
std::size_t taken_from_first(std::span<const T> a, std::span<const T> b, std::size_t rank) {
  std::size_t low = rank > b.size() ? rank - b.size() : 0, high = std::min(rank, a.size());
  while (low < high) {
    const std::size_t i = low + (high - low) / 2;
    if (b[rank - i - 1] < a[i]) {
      high = i;  // a[i] comes after the first `rank`
    } else {
      low = i + 1;
    }
  }
  return low;
}

// std::merge(a, b) into `out` (a.size() + b.size() elements), in `pieces` pieces on up to
// `threads` threads.
template <class T>
void merge_in_pieces(std::span<const T> a, std::span<const T> b, T* out, std::size_t pieces,
                     unsigned threads) {
  const std::size_t total = a.size() + b.size();
  pieces = std::clamp<std::size_t>(pieces, 1, std::max<std::size_t>(1, total));
  for_each_index(pieces, threads, [&](std::size_t piece) {
    const std::size_t begin = total * piece / pieces, end = total * (piece + 1) / pieces;
    const std::size_t a_begin = taken_from_first(a, b, begin), a_end = taken_from_first(a, b, end);
    std::merge(a.begin() + static_cast<std::ptrdiff_t>(a_begin),
               a.begin() + static_cast<std::ptrdiff_t>(a_end),
               b.begin() + static_cast<std::ptrdiff_t>(begin - a_begin),
               b.begin() + static_cast<std::ptrdiff_t>(end - a_end), out + begin);
  });
}

// The sorted `runs` merged into one sorted array, on up to `threads` threads.
template <class T>
std::vector<T> merge_runs(std::vector<std::vector<T>> runs, unsigned threads) {
  if (runs.empty()) return {};
  while (runs.size() > 1) {
    std::vector<std::vector<T>> merged((runs.size() + 1) / 2);
    const std::size_t pairs = runs.size() / 2;
    for (std::size_t p = 0; p < pairs; ++p) {
      merged[p].resize(runs[2 * p].size() + runs[2 * p + 1].size());
    }
    // One merge after another, each on every thread: the pairs are few (one per thread at most).
    for (std::size_t p = 0; p < pairs; ++p) {
      merge_in_pieces<T>(runs[2 * p], runs[2 * p + 1], merged[p].data(), threads, threads);
      std::vector<T>().swap(runs[2 * p]);
      std::vector<T>().swap(runs[2 * p + 1]);
    }
    if (runs.size() % 2 == 1) merged.back() = std::move(runs.back());
    runs = std::move(merged);
  }
  return std::move(runs.front());
}

}  // namespace holefill::detail
