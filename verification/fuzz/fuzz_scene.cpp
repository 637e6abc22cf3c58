// The libFuzzer target over the scene loader and a bounded run of the loaded scene (built only
// with clang and GP_FUZZ=ON; ./test.sh runs it for 60 s). Any exception but InputError and
// NumericalError escapes run_scene_input and libFuzzer reports it as a crash.
#include <cstddef>
#include <cstdint>
#include <string>

#include "verification/fuzz/scene_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  gp::fuzz::run_scene_input(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
