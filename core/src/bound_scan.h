// The apex loop's first test over many apexes at once (full_search.cpp). A candidate apex's value
// is at least the lane-wise maximum of its two sides' keys (weight_key::lane_max), so it can beat
// a cell's best only when that is at most the best key; the keys of a row's left sides and of a
// column's right sides lie contiguously, so most apexes are ruled out four at a time.
#pragma once

#include <cstdint>

namespace holefill::detail {

// A function returning the first j in [0, count) with weight_key::lane_max(left[j], right[j]) <=
// best, or count when there is none.
using BoundScan = int (*)(const std::uint64_t* left, const std::uint64_t* right, int count,
                          std::uint64_t best);

// The fastest BoundScan this processor runs (AVX2 where it has it); choose once, call often.
BoundScan fastest_bound_scan();

// The BoundScan without SIMD, for any processor (tests compare the two).
int first_within_bound_portable(const std::uint64_t* left, const std::uint64_t* right, int count,
                                std::uint64_t best);

}  // namespace holefill::detail
