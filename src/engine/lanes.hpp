#pragma once
// How many doubles the engine's SIMD paths take in one register on this build and CPU, asked once
// when the program starts, or fewer where limit_lanes asks. Every path gives the same bits as the
// one-at-a-time loop it stands for.

// The AVX2 paths are built for x86-64 with GCC or Clang, and taken where the CPU has AVX2.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define GP_LANES_AVX2 1
#else
#define GP_LANES_AVX2 0
#endif

#include <string>

namespace gp {

/// One double at a time (the scalar loop), two (SSE2) or four (AVX2).
enum class Lanes { kOne, kTwo, kFour };

/// The widest the SIMD paths take now: this build's and CPU's, unless limit_lanes asked for fewer.
/// Read before the program starts, it is kOne, which gives the same bits.
Lanes widest_lanes();

/// From now on the SIMD paths take at most `most` lanes, and no more than the CPU has. Every width
/// gives the same bits, which a run on fewer lanes shows. Call it between runs, not during one.
void limit_lanes(Lanes most);

/// The lanes that take `doubles` doubles at a time (1, 2 or 4), as a user asked for them in
/// `field` (the command line's --lanes, Python's set_lanes); throws an InputError naming `field`
/// for another count.
Lanes lanes_of(int doubles, const std::string& field);

/// How many doubles `lanes` take at a time: 1, 2 or 4.
int doubles_of(Lanes lanes);

/// Whether the four-lane (AVX2) paths run: widest_lanes() is kFour.
inline bool four_lanes() {
  return widest_lanes() == Lanes::kFour;
}

}  // namespace gp
