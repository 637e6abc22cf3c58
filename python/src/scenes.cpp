// Scene files for Python: load_scene checks a file as the command line does (the same messages,
// with the file's name), simulate runs it into NumPy arrays, and oracle solves it with the
// SUNDIALS oracle into arrays of the same shape.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "engine/output/output_times.hpp"
#include "engine/scene/run.hpp"
#include "engine/scene/scene_space.hpp"
#include "scene/input_error.hpp"
#include "scene/scene.hpp"
#include "verification/oracle/oracle.hpp"

namespace py = pybind11;

namespace gp::python {

namespace {

/// A scene file, read and checked, with where it came from.
struct SceneFile {
  std::string path;
  Scene scene;
};

/// The scene in `path` with `overrides`, checked whole (its bodies too, by building a space), or
/// an InputError whose message starts with the file, as the command line's does.
SceneFile load(const std::string& path, const SceneOverrides& overrides) {
  try {
    SceneFile file{path, load_scene(path, overrides)};
    build_space(file.scene);
    return file;
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.field(), e.rule(), e.value());
  }
}

/// Arrays for the states of every body of `scene` at its output instants: t (n) and
/// (n, bodies, 6) of x, y, ϕ, vx, vy, ω, filled by `store`(k, body, state).
struct StateArrays {
  explicit StateArrays(const Scene& scene)
      : instants(OutputTimes(scene.duration, scene.output_dt).size()),
        bodies(scene.bodies.size()),
        t(static_cast<py::ssize_t>(instants)),
        states({static_cast<py::ssize_t>(instants), static_cast<py::ssize_t>(bodies),
                py::ssize_t{6}}) {
    for (const BodyDef& b : scene.bodies) names.push_back(b.name);
  }

  void store(py::ssize_t k, double now, std::size_t body, const BodyState& s) {
    t.mutable_unchecked<1>()(k) = now;
    auto values = states.mutable_unchecked<3>();
    const double row[6] = {s.position.x(), s.position.y(), s.angle,
                           s.velocity.x(), s.velocity.y(), s.angular_velocity};
    for (py::ssize_t q = 0; q < 6; ++q) values(k, static_cast<py::ssize_t>(body), q) = row[q];
  }

  py::tuple result() const { return py::make_tuple(t, names, states); }

  std::size_t instants;
  std::size_t bodies;
  py::array_t<double> t;
  py::array_t<double> states;
  std::vector<std::string> names;
};

/// The engine's run of the scene at every output instant, on the threads of set_threads.
py::tuple run(const SceneFile& file) {
  const Scene& scene = file.scene;
  const std::unique_ptr<Space> space = build_space(scene);
  StateArrays arrays(scene);
  py::ssize_t k = 0;
  on_engine_threads([&] {
    run_scene(*space, scene, [&](double now) {
      for (BodyId j = 0; j < arrays.bodies; ++j) arrays.store(k, now, j, space->state(j));
      ++k;
    });
  });
  return arrays.result();
}

/// The oracle's solution of the scene at every output instant (verification/oracle).
py::tuple solve(const SceneFile& file, const std::string& method, double rtol, double atol,
                double step) {
  const Scene& scene = file.scene;
  verification::OracleOptions options;
  const auto chosen = verification::oracle_method_from_name(method);
  if (!chosen) {
    throw InputError("method", "must be cvode-adams, cvode-bdf, arkode-erk or time-stepping",
                     method);
  }
  options.method = *chosen;
  options.rtol = rtol;
  options.atol = atol;
  options.step = step;
  StateArrays arrays(scene);
  const OutputTimes output(scene.duration, scene.output_dt);
  std::vector<double> times;
  for (std::size_t k = 0; k < output.size(); ++k) times.push_back(output[k]);
  try {
    const verification::OracleResult r = verification::run_oracle(scene, times, options);
    for (std::size_t k = 0; k < times.size(); ++k) {
      for (std::size_t j = 0; j < arrays.bodies; ++j) {
        arrays.store(static_cast<py::ssize_t>(k), times[k], j, r.states[k][j]);
      }
    }
  } catch (const verification::OracleDomainError& e) {
    throw std::domain_error(file.path + ": " + e.what());
  }
  return arrays.result();
}

}  // namespace

void bind_scenes(py::module_& m) {
  py::class_<SceneFile>(m, "Scene", "A scene file (docs/scene-format.md), read and checked.")
      .def_readonly("path", &SceneFile::path)
      .def_property_readonly(
          "dt", [](const SceneFile& f) { return f.scene.dt; }, "s")
      .def_property_readonly(
          "duration", [](const SceneFile& f) { return f.scene.duration; }, "s")
      .def_property_readonly(
          "output_dt", [](const SceneFile& f) { return f.scene.output_dt; }, "s")
      .def_property_readonly("settings", [](const SceneFile& f) { return f.scene.settings; })
      .def_property_readonly("bodies", [](const SceneFile& f) { return f.scene.bodies; })
      .def(
          "space", [](const SceneFile& f) { return build_space(f.scene); },
          "A new Space with the scene's settings and bodies, at t = 0 (body i is id i).");
  m.def(
      "load_scene",
      [](const std::string& path, std::optional<std::string> integrator, std::optional<double> dt,
         std::optional<double> duration, std::optional<double> output_dt) {
        return load(path, {integrator, dt, duration, output_dt});
      },
      py::arg("path"), py::arg("integrator") = std::nullopt, py::arg("dt") = std::nullopt,
      py::arg("duration") = std::nullopt, py::arg("output_dt") = std::nullopt,
      "Reads and checks a scene file; the options replace the file's values, as the command "
      "line's do. Raises InputError with the command line's message.");
  m.def("_run", &run, py::arg("scene"));
  m.def("_oracle", &solve, py::arg("scene"), py::arg("method"), py::arg("rtol"), py::arg("atol"),
        py::arg("step"));
}

}  // namespace gp::python
