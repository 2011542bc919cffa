// The apex loop's first tests over many apexes at once (full_search.cpp). A candidate apex's value
// is at least the lane-wise maximum of its two sides' keys (weight_key::lane_max), so it can beat
// a cell's best only when that is at most the best key; when it equals the best key, the
// candidate's area decides, and the sides' areas plus its triangle's must be smaller than the
// best's. The keys and areas of a row's left sides and of a column's right sides lie
// contiguously, so most apexes are ruled out four at a time, ties included.
#pragma once

#include <cstdint>

namespace holefill::detail {

// A candidate tied with the best on key loses when its area is larger: when twice its triangle's
// area exceeds the root of this, the area exceeds the best's whatever the rounding, since the room
// is widened by a millionth of the best area (a candidate in that margin takes the exact test).
// Comparing squares spares the root for most tied candidates, which are rejected here.
inline double squared_twice_room(double best_area, double sides_lower_bound) {
  const double room = (best_area - sides_lower_bound) + 1e-6 * best_area;
  return 4.0 * room * room;
}

// Candidates m = first ... first + count - 1 of cell (i, k): each array starts at m = first.
struct ApexRun {
  const std::uint64_t* left_key;   // of side (i, m)
  const std::uint64_t* right_key;  // of side (m, k)
  const double* left_area;         // of side (i, m)
  const float* right_area;         // a lower bound of side (m, k)'s area
  const double* x;                 // point m's coordinates
  const double* y;
  const double* z;
  int count;
};

// What the candidates of one cell share: point i, and the edge from point i to point k.
struct ApexBase {
  double origin[3];
  double to_k[3];
};

// The best value found so far for the cell.
struct BestSoFar {
  std::uint64_t key;
  double area;
};

// A function returning the first j in [0, count) that may beat `best`, or count when none can:
// j is ruled out when lane_max(left_key[j], right_key[j]) > best.key, or when it equals best.key
// and either left_area[j] + right_area[j] > best.area or the squared cross product of
// (point j - origin) and to_k exceeds squared_twice_room(best.area, left_area[j] + right_area[j]).
// A j that is not ruled out may still lose (the exact tests follow); one ruled out always loses.
using BoundScan = int (*)(const ApexRun& run, const ApexBase& base, BestSoFar best);

// The fastest BoundScan this processor runs (AVX2 where it has it); choose once, call often.
BoundScan fastest_bound_scan();

// The BoundScan without SIMD, for any processor (tests compare the two).
int first_within_bound_portable(const ApexRun& run, const ApexBase& base, BestSoFar best);

}  // namespace holefill::detail
