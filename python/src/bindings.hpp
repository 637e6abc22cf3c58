#pragma once
// The parts of the Python module gamephysics._core, each defined in its own file.

#include <utility>

#include <pybind11/pybind11.h>
#include <tbb/task_arena.h>

namespace gp::python {

/// Settings, shapes, body definitions, body state and Space (space.cpp).
void bind_space(pybind11::module_& m);
/// Scene, load_scene and simulate (scenes.cpp).
void bind_scenes(pybind11::module_& m);
/// The SRS model functions as the submodules models.tm, .gd, .dd and .im (models.cpp).
void bind_models(pybind11::module_& m);
/// set_threads and threads (threads.cpp).
void bind_threads(pybind11::module_& m);
/// set_lanes and lanes (lanes.cpp).
void bind_lanes(pybind11::module_& m);

/// The task arena of as many threads as set_threads asked for (threads.cpp).
tbb::task_arena& engine_arena();

/// work(), run on the engine's threads: those of engine_arena().
template <typename Work>
auto on_engine_threads(Work&& work) {
  return engine_arena().execute(std::forward<Work>(work));
}

}  // namespace gp::python
