// The libFuzzer target over the scene loader and a bounded run of the loaded scene (built only
// with clang and GP_FUZZ=ON; ./test.sh runs it on 2 × 50,000 inputs). Any exception but
// InputError and NumericalError escapes run_scene_input and libFuzzer reports it as a crash.
#include <cstddef>
#include <cstdint>
#include <string>

#include <tbb/global_control.h>

#include "verification/fuzz/scene_input.hpp"

namespace {

// One thread: the inputs' scenes are small, so threads would only add their cost to each input
// (20,000 inputs in 12 s on one core against 22 s on two), and the coverage libFuzzer steers by
// would vary with how tasks are stolen, parting the inputs of two runs with the same seed.
const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  gp::fuzz::run_scene_input(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
