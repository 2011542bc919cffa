#include "bound_scan.h"

#include <algorithm>

#include "weight_keys.h"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace holefill::detail {
namespace {

#if defined(__x86_64__)
// AVX2 takes the 16-bit lanes' maxima in one instruction, and compares 64-bit lanes as signed
// integers only: flipping the sign bit of both sides turns the unsigned order into the signed one.
[[gnu::target("avx2")]] int first_within_bound_avx2(const std::uint64_t* left,
                                                    const std::uint64_t* right, int count,
                                                    std::uint64_t best) {
  const __m256i sign = _mm256_set1_epi64x(INT64_MIN);
  const __m256i limit = _mm256_xor_si256(_mm256_set1_epi64x(static_cast<long long>(best)), sign);
  int j = 0;
  for (; j + 4 <= count; j += 4) {
    const __m256i l = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(left + j));
    const __m256i r = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(right + j));
    const __m256i bound = _mm256_xor_si256(_mm256_max_epu16(l, r), sign);
    const int over_mask = _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_cmpgt_epi64(bound, limit)));
    if (over_mask != 0xF) return j + __builtin_ctz(~over_mask & 0xF);
  }
  for (; j < count; ++j) {
    if (weight_key::lane_max(left[j], right[j]) <= best) return j;
  }
  return count;
}
#endif

}  // namespace

int first_within_bound_portable(const std::uint64_t* left, const std::uint64_t* right, int count,
                                std::uint64_t best) {
  // Blocks of eight with no branch inside (a running minimum of the bounds), then the exact
  // position.
  int j = 0;
  for (; j + 8 <= count; j += 8) {
    std::uint64_t smallest = weight_key::lane_max(left[j], right[j]);
    for (int t = 1; t < 8; ++t) {
      smallest = std::min(smallest, weight_key::lane_max(left[j + t], right[j + t]));
    }
    if (smallest <= best) break;
  }
  for (; j < count; ++j) {
    if (weight_key::lane_max(left[j], right[j]) <= best) return j;
  }
  return count;
}

BoundScan fastest_bound_scan() {
#if defined(__x86_64__)
  if (__builtin_cpu_supports("avx2")) return first_within_bound_avx2;
#endif
  return first_within_bound_portable;
}

}  // namespace holefill::detail
