#pragma once
// What the engine's AVX2 paths share: the lanes of 256-bit registers of doubles. Include it only
// under GP_LANES_AVX2 (engine/lanes.hpp); its functions are compiled for AVX2 alone.

#include <immintrin.h>

#include <array>

#include "engine/core.hpp"

namespace gp {

/// Four doubles, a lane each.
using Four = __m256d;

/// Four points, (x0, y0, x1, y1) in `low` and (x2, y2, x3, y3) in `high`, into x = (x0, x1, x2,
/// x3) and y = (y0, y1, y2, y3): unpacking the two halves gives (x0, x2, x1, x3), and the
/// permutation puts its middle lanes back in order.
[[gnu::target("avx2")]] inline void split_xy(__m256d low, __m256d high, __m256d& x, __m256d& y) {
  constexpr int kMiddleSwapped = 0b11'01'10'00;
  x = _mm256_permute4x64_pd(_mm256_unpacklo_pd(low, high), kMiddleSwapped);
  y = _mm256_permute4x64_pd(_mm256_unpackhi_pd(low, high), kMiddleSwapped);
}

/// split_xy undone: x and y lanes back into (x0, y0, x1, y1) in `low` and (x2, y2, x3, y3) in
/// `high` (the permutation is its own inverse).
[[gnu::target("avx2")]] inline void join_xy(__m256d x, __m256d y, __m256d& low, __m256d& high) {
  constexpr int kMiddleSwapped = 0b11'01'10'00;
  const __m256d xs = _mm256_permute4x64_pd(x, kMiddleSwapped);
  const __m256d ys = _mm256_permute4x64_pd(y, kMiddleSwapped);
  low = _mm256_unpacklo_pd(xs, ys);
  high = _mm256_unpackhi_pd(xs, ys);
}

/// Four fields of four records: field[k] holds field k of each record, a lane each.
struct FourFields {
  __m256d field[4];
};

/// Four rows of four doubles, a record's fields each, into their columns.
[[gnu::target("avx2")]] inline FourFields transpose(__m256d r0, __m256d r1, __m256d r2,
                                                    __m256d r3) {
  // (r0[0], r1[0], r0[2], r1[2]), (r0[1], r1[1], r0[3], r1[3]), and the same of r2 and r3; then
  // their low halves side by side, and their high halves.
  const __m256d even01 = _mm256_unpacklo_pd(r0, r1);
  const __m256d odd01 = _mm256_unpackhi_pd(r0, r1);
  const __m256d even23 = _mm256_unpacklo_pd(r2, r3);
  const __m256d odd23 = _mm256_unpackhi_pd(r2, r3);
  constexpr int kLowHalves = 0x20;
  constexpr int kHighHalves = 0x31;
  return {{_mm256_permute2f128_pd(even01, even23, kLowHalves),
           _mm256_permute2f128_pd(odd01, odd23, kLowHalves),
           _mm256_permute2f128_pd(even01, even23, kHighHalves),
           _mm256_permute2f128_pd(odd01, odd23, kHighHalves)}};
}

/// All ones in each of the first n of four lanes.
[[gnu::target("avx2")]] inline __m256i first_lanes(std::size_t n) {
  return _mm256_cmpgt_epi64(_mm256_set1_epi64x(static_cast<long long>(n)),
                            _mm256_set_epi64x(3, 2, 1, 0));
}

/// Four vectors, anywhere, into their x and y lanes.
[[gnu::target("avx2")]] inline void split(const Vec2& v0, const Vec2& v1, const Vec2& v2,
                                          const Vec2& v3, Four& x, Four& y) {
  split_xy(_mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(v0.data())),
                                _mm_loadu_pd(v1.data()), 1),
           _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(v2.data())),
                                _mm_loadu_pd(v3.data()), 1),
           x, y);
}

/// values[b[l]] in lane l.
[[gnu::target("avx2")]] inline Four gather(const double* values, const std::array<BodyId, 4>& b) {
  return _mm256_set_pd(values[b[3]], values[b[2]], values[b[1]], values[b[0]]);
}

/// std::max(a, b) and std::min(a, b) lane by lane, equal values and NaN included: each gives its
/// first argument unless the second is larger (smaller), where the instructions give their second
/// operand unless the first is.
[[gnu::target("avx2")]] inline Four max_of(Four a, Four b) {
  return _mm256_max_pd(b, a);
}
[[gnu::target("avx2")]] inline Four min_of(Four a, Four b) {
  return _mm256_min_pd(b, a);
}
/// |x| lane by lane.
[[gnu::target("avx2")]] inline Four magnitude(Four x) {
  return _mm256_andnot_pd(_mm256_set1_pd(-0.0), x);
}

/// `after` in the lanes of `mask`, `before` in the others.
[[gnu::target("avx2")]] inline Four where(Four mask, Four before, Four after) {
  return _mm256_blendv_pd(before, after, mask);
}

}  // namespace gp
