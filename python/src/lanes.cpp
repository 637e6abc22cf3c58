// The width of the engine's SIMD paths from Python, as the command line's --lanes: to check that
// every width gives the same numbers.
#include "engine/lanes.hpp"
#include "bindings.hpp"

namespace gp::python {

void bind_lanes(pybind11::module_& m) {
  m.def(
      "set_lanes", [](int lanes) { limit_lanes(lanes_of(lanes, "lanes")); }, pybind11::arg("lanes"),
      "The doubles the engine's SIMD paths take at a time from now on: 1 (one at a time), 2 "
      "(SSE2) or 4 (AVX2), at most what the CPU has (the widest by default, as the command "
      "line's --lanes). Results are the same to the bit on any width.");
  m.def(
      "lanes", [] { return doubles_of(widest_lanes()); },
      "The doubles the engine's SIMD paths take at a time now: 1, 2 or 4.");
}

}  // namespace gp::python
