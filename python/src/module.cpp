// gamephysics._core: the engine for Python, bound rather than copied. The package gamephysics
// (python/gamephysics/) re-exports it.
#include "bindings.hpp"
#include "engine/numerical_error.hpp"
#include "scene/input_error.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "GamePhysics: 2D rigid bodies after the GamePhysics SRS (Drasil).";
  // The messages are the command line's: "bodies[0].mass: must be > 0 (...), got -1".
  pybind11::register_exception<gp::InputError>(m, "InputError", PyExc_ValueError);
  pybind11::register_exception<gp::NumericalError>(m, "NumericalError", PyExc_ArithmeticError);
  gp::python::bind_space(m);
  gp::python::bind_scenes(m);
  gp::python::bind_models(m);
  gp::python::bind_threads(m);
  gp::python::bind_lanes(m);
}
