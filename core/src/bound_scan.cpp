#include "bound_scan.h"

#include <algorithm>

#include "weight_keys.h"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace holefill::detail {
namespace {

// Whether a candidate tied with the best on key is ruled out by its area (BoundScan).
bool tie_ruled_out_by_area(const ApexRun& run, const ApexBase& base, BestSoFar best, int j) {
  const double sides = run.left_area[j] + static_cast<double>(run.right_area[j]);
  if (sides > best.area) return true;
  const double tx = run.x[j] - base.origin[0], ty = run.y[j] - base.origin[1],
               tz = run.z[j] - base.origin[2];
  const double cx = ty * base.to_k[2] - tz * base.to_k[1];
  const double cy = tz * base.to_k[0] - tx * base.to_k[2];
  const double cz = tx * base.to_k[1] - ty * base.to_k[0];
  return cx * cx + cy * cy + cz * cz > squared_twice_room(best.area, sides);
}

bool ruled_out(const ApexRun& run, const ApexBase& base, BestSoFar best, int j) {
  const std::uint64_t bound = weight_key::lane_max(run.left_key[j], run.right_key[j]);
  return bound > best.key || (bound == best.key && tie_ruled_out_by_area(run, base, best, j));
}

#if defined(__x86_64__)
// AVX2 takes the 16-bit lanes' maxima in one instruction, and compares 64-bit lanes as signed
// integers only: flipping the sign bit of both sides turns the unsigned order into the signed one.
// Blocks whose every key is over the bound (most) never touch the areas or the points.
[[gnu::target("avx2")]] int first_within_bound_avx2(const ApexRun& run, const ApexBase& base,
                                                    BestSoFar best) {
  const __m256i sign = _mm256_set1_epi64x(INT64_MIN);
  const __m256i limit =
      _mm256_xor_si256(_mm256_set1_epi64x(static_cast<long long>(best.key)), sign);
  const __m256d best_area = _mm256_set1_pd(best.area);
  const __m256d margin = _mm256_set1_pd(1e-6 * best.area);
  const __m256d ox = _mm256_set1_pd(base.origin[0]), oy = _mm256_set1_pd(base.origin[1]),
                oz = _mm256_set1_pd(base.origin[2]);
  const __m256d kx = _mm256_set1_pd(base.to_k[0]), ky = _mm256_set1_pd(base.to_k[1]),
                kz = _mm256_set1_pd(base.to_k[2]);
  int j = 0;
  for (; j + 4 <= run.count; j += 4) {
    const __m256i l = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(run.left_key + j));
    const __m256i r = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(run.right_key + j));
    const __m256i bound = _mm256_xor_si256(_mm256_max_epu16(l, r), sign);
    const int over = _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_cmpgt_epi64(bound, limit)));
    if (over == 0xF) continue;
    const int tie = _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_cmpeq_epi64(bound, limit)));
    int out = over;
    if ((tie & ~over) != 0) {
      // The tests of tie_ruled_out_by_area, four at a time (a NaN rules nothing out).
      const __m256d sides = _mm256_add_pd(_mm256_loadu_pd(run.left_area + j),
                                          _mm256_cvtps_pd(_mm_loadu_ps(run.right_area + j)));
      const __m256d tx = _mm256_sub_pd(_mm256_loadu_pd(run.x + j), ox);
      const __m256d ty = _mm256_sub_pd(_mm256_loadu_pd(run.y + j), oy);
      const __m256d tz = _mm256_sub_pd(_mm256_loadu_pd(run.z + j), oz);
      const __m256d cx = _mm256_sub_pd(_mm256_mul_pd(ty, kz), _mm256_mul_pd(tz, ky));
      const __m256d cy = _mm256_sub_pd(_mm256_mul_pd(tz, kx), _mm256_mul_pd(tx, kz));
      const __m256d cz = _mm256_sub_pd(_mm256_mul_pd(tx, ky), _mm256_mul_pd(ty, kx));
      const __m256d squared_cross = _mm256_add_pd(
          _mm256_add_pd(_mm256_mul_pd(cx, cx), _mm256_mul_pd(cy, cy)), _mm256_mul_pd(cz, cz));
      const __m256d room = _mm256_add_pd(_mm256_sub_pd(best_area, sides), margin);
      const __m256d squared_twice = _mm256_mul_pd(_mm256_set1_pd(4.0), _mm256_mul_pd(room, room));
      const __m256d area_out =
          _mm256_or_pd(_mm256_cmp_pd(sides, best_area, _CMP_GT_OQ),
                       _mm256_cmp_pd(squared_cross, squared_twice, _CMP_GT_OQ));
      out |= tie & _mm256_movemask_pd(area_out);
    }
    if (out != 0xF) return j + __builtin_ctz(~out & 0xF);
  }
  for (; j < run.count; ++j) {
    if (!ruled_out(run, base, best, j)) return j;
  }
  return run.count;
}
#endif

}  // namespace

int first_within_bound_portable(const ApexRun& run, const ApexBase& base, BestSoFar best) {
  // Blocks of eight keys with no branch inside (a running minimum of the bounds), then the exact
  // tests one by one.
  int j = 0;
  for (; j + 8 <= run.count; j += 8) {
    std::uint64_t smallest = weight_key::lane_max(run.left_key[j], run.right_key[j]);
    for (int t = 1; t < 8; ++t) {
      smallest =
          std::min(smallest, weight_key::lane_max(run.left_key[j + t], run.right_key[j + t]));
    }
    if (smallest > best.key) continue;
    for (int t = 0; t < 8; ++t) {
      if (!ruled_out(run, base, best, j + t)) return j + t;
    }
  }
  for (; j < run.count; ++j) {
    if (!ruled_out(run, base, best, j)) return j;
  }
  return run.count;
}

BoundScan fastest_bound_scan() {
#if defined(__x86_64__)
  if (__builtin_cpu_supports("avx2")) return first_within_bound_avx2;
#endif
  return first_within_bound_portable;
}

}  // namespace holefill::detail
