#pragma once
// How many doubles the engine's SIMD paths take in one register on this build and CPU, asked once
// when the program starts. Every path gives the same bits as the one-at-a-time loop it stands for.

// The AVX2 paths are built for x86-64 with GCC or Clang, and taken where the CPU has AVX2.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define GP_LANES_AVX2 1
#else
#define GP_LANES_AVX2 0
#endif

namespace gp {

/// One double at a time (the scalar loop), two (SSE2) or four (AVX2).
enum class Lanes { kOne, kTwo, kFour };

/// The widest this build and CPU have. Read before the program starts, it is kOne, which gives
/// the same bits.
Lanes widest_lanes();

/// Narrows the SIMD paths to at most `most` lanes from now on; the CPU's widest still bounds them.
/// Every width gives the same bits, which a run on fewer lanes shows. Call it before a run, not
/// during one.
void limit_lanes(Lanes most);

/// Whether the four-lane (AVX2) paths run: widest_lanes() is kFour.
inline bool four_lanes() {
  return widest_lanes() == Lanes::kFour;
}

}  // namespace gp
