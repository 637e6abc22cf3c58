#include "engine/lanes.hpp"

#include <algorithm>

#include "scene/input_error.hpp"

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

// The CPU's, asked once; and the widest the SIMD paths may take, which they read at every call.
const Lanes cpu_widest = widest_on_this_cpu();
Lanes widest = cpu_widest;

}  // namespace

Lanes widest_lanes() {
  return widest;
}

void limit_lanes(Lanes most) {
  widest = std::min(cpu_widest, most);
}

Lanes lanes_of(int doubles, const std::string& field) {
  switch (doubles) {
    case 1:
      return Lanes::kOne;
    case 2:
      return Lanes::kTwo;
    case 4:
      return Lanes::kFour;
    default:
      throw InputError(field, "must be 1, 2 or 4", std::to_string(doubles));
  }
}

int doubles_of(Lanes lanes) {
  switch (lanes) {
    case Lanes::kOne:
      break;
    case Lanes::kTwo:
      return 2;
    case Lanes::kFour:
      return 4;
  }
  return 1;
}

}  // namespace gp
