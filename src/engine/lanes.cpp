#include "engine/lanes.hpp"

#include <algorithm>

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

// Asked once, and narrowed only by limit_lanes: the SIMD paths read it at every call.
Lanes widest = widest_on_this_cpu();

}  // namespace

Lanes widest_lanes() {
  return widest;
}

void limit_lanes(Lanes most) {
  widest = std::min(widest, most);
}

}  // namespace gp
