#pragma once
// What the engine's AVX2 paths share: the lanes of 256-bit registers of doubles. Include it only
// under GP_LANES_AVX2 (engine/lanes.hpp); its functions are compiled for AVX2 alone.

#include <immintrin.h>

namespace gp {

/// Four points, (x0, y0, x1, y1) in `low` and (x2, y2, x3, y3) in `high`, into x = (x0, x1, x2,
/// x3) and y = (y0, y1, y2, y3): unpacking the two halves gives (x0, x2, x1, x3), and the
/// permutation puts its middle lanes back in order.
[[gnu::target("avx2")]] inline void split_xy(__m256d low, __m256d high, __m256d& x, __m256d& y) {
  constexpr int kMiddleSwapped = 0b11'01'10'00;
  x = _mm256_permute4x64_pd(_mm256_unpacklo_pd(low, high), kMiddleSwapped);
  y = _mm256_permute4x64_pd(_mm256_unpackhi_pd(low, high), kMiddleSwapped);
}

}  // namespace gp
