// The width of the engine's SIMD paths from Python, as the command line's --lanes: to check that
// every width gives the same numbers.
#include <optional>
#include <string>

#include "bindings.hpp"
#include "engine/lanes.hpp"
#include "scene/input_error.hpp"

namespace gp::python {

void bind_lanes(pybind11::module_& m) {
  m.def(
      "set_lanes",
      [](int lanes) {
        const std::optional<Lanes> most = lanes_of(lanes);
        if (!most) throw InputError("lanes", "must be 1, 2 or 4", std::to_string(lanes));
        limit_lanes(*most);
      },
      pybind11::arg("lanes"),
      "The doubles the engine's SIMD paths take at a time from now on: 1 (one at a time), 2 "
      "(SSE2) or 4 (AVX2), at most what the CPU has (the widest by default, as the command "
      "line's --lanes). Results are the same to the bit on any width.");
  m.def(
      "lanes", [] { return doubles_of(widest_lanes()); },
      "The doubles the engine's SIMD paths take at a time now: 1, 2 or 4.");
}

}  // namespace gp::python
