// The threads the engine runs on from Python: one by default, as the command line's --threads,
// since a teacher's scene of a few bodies runs slower when threads share its step.
#include "bindings.hpp"
#include "engine/thread_count.hpp"

namespace gp::python {

namespace {

// The count set_threads was given (0: every core).
int& chosen_threads() {
  static int threads = 1;
  return threads;
}

}  // namespace

tbb::task_arena& engine_arena() {
  static tbb::task_arena arena(1);
  return arena;
}

void bind_threads(pybind11::module_& m) {
  m.def(
      "set_threads",
      [](int threads) {
        const std::size_t count = thread_count(threads, "threads");
        tbb::task_arena& arena = engine_arena();
        arena.terminate();
        arena.initialize(count == 0 ? tbb::task_arena::automatic : static_cast<int>(count));
        chosen_threads() = threads;
      },
      pybind11::arg("threads"),
      "The threads Space.step and simulate run on from now on (0: every core; 1 by default, as "
      "the command line's --threads). Results are the same to the bit on any number.");
  m.def(
      "threads", [] { return chosen_threads(); },
      "The count last given to set_threads (1 by default; 0: every core).");
}

}  // namespace gp::python
