// Scene files for Python: load_scene checks a file as the command line does (the same messages,
// with the file's name), and simulate runs it into NumPy arrays.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "scene/input_error.hpp"
#include "engine/output/output_times.hpp"
#include "engine/scene/run.hpp"
#include "engine/scene/scene_space.hpp"
#include "scene/scene.hpp"

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

/// The states at every output instant: t (n), and (n, bodies, 6) of x, y, ϕ, vx, vy, ω.
py::tuple run(const SceneFile& file) {
  const Scene& scene = file.scene;
  const std::unique_ptr<Space> space = build_space(scene);
  const std::size_t bodies = space->body_count();
  const std::size_t instants = OutputTimes(scene.duration, scene.output_dt).size();
  py::array_t<double> t(static_cast<py::ssize_t>(instants));
  py::array_t<double> states(
      {static_cast<py::ssize_t>(instants), static_cast<py::ssize_t>(bodies), py::ssize_t{6}});
  auto times = t.mutable_unchecked<1>();
  auto values = states.mutable_unchecked<3>();
  py::ssize_t k = 0;
  run_scene(*space, scene, [&](double now) {
    times(k) = now;
    for (BodyId j = 0; j < bodies; ++j) {
      const BodyState s = space->state(j);
      const double row[6] = {s.position.x(), s.position.y(), s.angle,
                             s.velocity.x(), s.velocity.y(), s.angular_velocity};
      for (py::ssize_t q = 0; q < 6; ++q) values(k, j, q) = row[q];
    }
    ++k;
  });
  std::vector<std::string> names;
  for (BodyId j = 0; j < bodies; ++j) names.emplace_back(space->name(j));
  return py::make_tuple(t, names, states);
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
}

}  // namespace gp::python
