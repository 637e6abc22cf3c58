#include "engine/lanes.hpp"

namespace gp {

namespace {

Lanes widest_on_this_cpu() {
#if GP_LANES_AVX2
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2")) return Lanes::kFour;
#endif
#if defined(__SSE2__)
  return Lanes::kTwo;
#else
  return Lanes::kOne;
#endif
}

// Asked once: the SIMD paths read it at every call.
const Lanes widest = widest_on_this_cpu();

}  // namespace

Lanes widest_lanes() {
  return widest;
}

}  // namespace gp
