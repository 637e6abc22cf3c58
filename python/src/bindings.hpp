#pragma once
// The parts of the Python module gamephysics._core, each defined in its own file.

#include <pybind11/pybind11.h>

namespace gp::python {

/// Settings, shapes, body definitions, body state and Space (space.cpp).
void bind_space(pybind11::module_& m);
/// Scene, load_scene and simulate (scenes.cpp).
void bind_scenes(pybind11::module_& m);
/// The SRS model functions as the submodules models.tm, .gd, .dd and .im (models.cpp).
void bind_models(pybind11::module_& m);

}  // namespace gp::python
