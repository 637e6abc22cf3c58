// Space and what it is made of, for Python: settings, shapes, body definitions and states. Vectors
// are NumPy arrays of two numbers (any sequence of two is taken); units are SI throughout.
#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "engine/space.hpp"
#include "scene/body.hpp"
#include "scene/input_error.hpp"
#include "scene/settings.hpp"
#include "scene/shape.hpp"

namespace py = pybind11;

namespace gp::python {

namespace {

void bind_settings(py::module_& m) {
  py::enum_<IntegratorKind>(m, "Integrator", "The game integrators (LC:Variable-ODE-Solver).")
      .value("symplectic_euler", IntegratorKind::SymplecticEuler)
      .value("velocity_verlet", IntegratorKind::VelocityVerlet)
      .value("rk4", IntegratorKind::RK4);
  py::class_<Settings>(m, "Settings", "The forces of the world, the integrator and the solver.")
      .def(py::init([](const Vec2& gravity, std::optional<double> G, IntegratorKind integrator) {
             Settings s;
             s.gravity = gravity;
             s.G = G;
             s.integrator = integrator;
             return s;
           }),
           py::arg("gravity") = Vec2::Zero().eval(), py::arg("G") = std::nullopt,
           py::arg("integrator") = IntegratorKind::VelocityVerlet)
      .def_readwrite("gravity", &Settings::gravity, "g [m/s²], uniform")
      .def_readwrite("G", &Settings::G, "gravitational constant [m³/(kg·s²)], or None")
      .def_readwrite("integrator", &Settings::integrator)
      .def_readwrite("velocity_iterations", &Settings::velocity_iterations)
      .def_readwrite("position_iterations", &Settings::position_iterations)
      .def_readwrite("restitution_threshold", &Settings::restitution_threshold, "m/s")
      .def_readwrite("max_impacts_per_step", &Settings::max_impacts_per_step)
      .def_readwrite("sleep", &Settings::sleep, "islands at rest stop costing (off by default)")
      .def_readwrite("sleep_speed", &Settings::sleep_speed, "m/s")
      .def_readwrite("sleep_angular_speed", &Settings::sleep_angular_speed, "rad/s")
      .def_readwrite("time_to_sleep", &Settings::time_to_sleep, "s")
      .def_readwrite("coloured_island_contacts", &Settings::coloured_island_contacts,
                     "islands of more contacts are solved colour by colour (0: never)")
      .def_readwrite("island_part_contacts", &Settings::island_part_contacts,
                     "islands of more contacts are cut into parts that threads share (0: never)")
      .def_readwrite("island_parts", &Settings::island_parts,
                     "into how many parts such an island is cut (a power of two, 2 to 64)");
}

void bind_shapes(py::module_& m) {
  py::class_<Shape>(m, "Shape", "A shape in the body frame [m].")
      .def_static(
          "circle", [](double radius, const Vec2& center) { return Shape::circle(radius, center); },
          py::arg("radius"), py::arg("center") = Vec2::Zero().eval())
      .def_static(
          "box",
          [](double width, double height, const Vec2& center) {
            return Shape::box(width, height, center);
          },
          py::arg("width"), py::arg("height"), py::arg("center") = Vec2::Zero().eval())
      .def_static(
          "polygon", [](const std::vector<Vec2>& vertices) { return Shape::polygon(vertices); },
          py::arg("vertices"), "A convex polygon, vertices counter-clockwise.")
      .def_static(
          "segment",
          [](const Vec2& a, const Vec2& b, double radius) { return Shape::segment(a, b, radius); },
          py::arg("a"), py::arg("b"), py::arg("radius") = 0.0);
  // The shape factories refuse degenerate shapes with std::invalid_argument: a ValueError.
  py::class_<ShapeDef>(m, "ShapeDef", "A shape with its surface and density.")
      .def(py::init([](const Shape& shape, double restitution, double friction, double density) {
             return ShapeDef{shape, restitution, friction, density};
           }),
           py::arg("shape"), py::arg("restitution") = 0.0, py::arg("friction") = 0.0,
           py::arg("density") = 1.0)
      .def_readwrite("shape", &ShapeDef::shape)
      .def_readwrite("restitution", &ShapeDef::restitution, "C_R [1], 0 ≤ C_R ≤ 1")
      .def_readwrite("friction", &ShapeDef::friction, "μ [1], ≥ 0")
      .def_readwrite("density", &ShapeDef::density, "ρ [kg/m²], > 0");
}

void bind_bodies(py::module_& m) {
  py::enum_<BodyType>(m, "BodyType")
      .value("dynamic", BodyType::Dynamic)
      .value("static", BodyType::Static)
      .value("kinematic", BodyType::Kinematic);
  py::class_<BodyDef>(m, "BodyDef", "A body as the user describes it (docs/scene-format.md).")
      .def(py::init([](const std::string& name, BodyType type, const Vec2& position, double angle,
                       const Vec2& velocity, double angular_velocity, std::optional<double> mass,
                       std::optional<double> moment, const Vec2& force,
                       std::optional<Vec2> force_point, double torque,
                       const std::vector<ShapeDef>& shapes) {
             return BodyDef{name, type,   position, angle,       velocity, angular_velocity,
                            mass, moment, force,    force_point, torque,   shapes};
           }),
           py::arg("name"), py::arg("type") = BodyType::Dynamic,
           py::arg("position") = Vec2::Zero().eval(), py::arg("angle") = 0.0,
           py::arg("velocity") = Vec2::Zero().eval(), py::arg("angular_velocity") = 0.0,
           py::arg("mass") = std::nullopt, py::arg("moment") = std::nullopt,
           py::arg("force") = Vec2::Zero().eval(), py::arg("force_point") = std::nullopt,
           py::arg("torque") = 0.0, py::arg("shapes") = std::vector<ShapeDef>{})
      .def_readwrite("name", &BodyDef::name)
      .def_readwrite("type", &BodyDef::type)
      .def_readwrite("position", &BodyDef::position, "m: origin of the body frame")
      .def_readwrite("angle", &BodyDef::angle, "ϕ [rad]")
      .def_readwrite("velocity", &BodyDef::velocity, "m/s, of the centre of mass")
      .def_readwrite("angular_velocity", &BodyDef::angular_velocity, "ω [rad/s]")
      .def_readwrite("mass", &BodyDef::mass, "kg, or None (from the shapes)")
      .def_readwrite("moment", &BodyDef::moment, "I [kg·m²], or None (from the shapes)")
      .def_readwrite("force", &BodyDef::force, "N, constant")
      .def_readwrite("force_point", &BodyDef::force_point, "m, body frame, or None (the CoM)")
      .def_readwrite("torque", &BodyDef::torque, "N·m, constant")
      .def_readwrite("shapes", &BodyDef::shapes);
  py::class_<BodyState>(m, "BodyState", "A body's state at one instant.")
      .def_readonly("position", &BodyState::position, "centre of mass [m]")
      .def_readonly("angle", &BodyState::angle, "ϕ [rad] in [0, 2π)")
      .def_readonly("velocity", &BodyState::velocity, "of the centre of mass [m/s]")
      .def_readonly("angular_velocity", &BodyState::angular_velocity, "ω [rad/s]")
      .def("__repr__", [](const BodyState& s) {
        return "BodyState(position=[" + std::to_string(s.position.x()) + ", " +
               std::to_string(s.position.y()) + "], angle=" + std::to_string(s.angle) +
               ", velocity=[" + std::to_string(s.velocity.x()) + ", " +
               std::to_string(s.velocity.y()) +
               "], angular_velocity=" + std::to_string(s.angular_velocity) + ")";
      });
}

// A body given by id or by name.
using BodyRef = std::variant<BodyId, std::string>;

BodyId id_of(const Space& space, const BodyRef& body) {
  if (const auto* id = std::get_if<BodyId>(&body)) return *id;
  const std::string& name = std::get<std::string>(body);
  if (const auto id = space.find_body(name)) return *id;
  throw InputError("body", "must name a body of the space", '"' + name + '"');
}

/// A query of Space about a body, taking the body by id or by name.
template <typename Result>
auto of_body(Result (Space::*query)(BodyId) const) {
  return [query](const Space& s, const BodyRef& body) { return (s.*query)(id_of(s, body)); };
}

/// A change of a body's state, taking the body by id or by name.
template <typename Value>
auto by_body(void (Space::*change)(BodyId, Value)) {
  return
      [change](Space& s, const BodyRef& body, Value value) { (s.*change)(id_of(s, body), value); };
}

/// An impulse or a force at a point, which defaults to the body's centre of mass.
auto at_point(void (Space::*push)(BodyId, const Vec2&, const Vec2&)) {
  return [push](Space& s, const BodyRef& body, const Vec2& vector, std::optional<Vec2> point) {
    const BodyId id = id_of(s, body);
    (s.*push)(id, vector, point.value_or(s.state(id).position));
  };
}

void bind_space_class(py::module_& m) {
  py::class_<Wrench>(m, "Wrench", "A force [N] and a torque [N·m] about the centre of mass.")
      .def(py::init([](const Vec2& force, double torque) {
             return Wrench{force, torque};
           }),
           py::arg("force") = Vec2::Zero().eval(), py::arg("torque") = 0.0)
      .def_readwrite("force", &Wrench::force)
      .def_readwrite("torque", &Wrench::torque);
  py::class_<Impact>(m, "Impact", "A collision resolved at its time of impact t_c (IM:col2D).")
      .def_readonly("time", &Impact::time, "t_c [s]")
      .def_readonly("body_a", &Impact::body_a)
      .def_readonly("body_b", &Impact::body_b)
      .def_readonly("normal", &Impact::normal, "unit, from B towards A")
      .def_readonly("point", &Impact::point, "m, world: the mean of the contact points")
      .def_readonly("impulse", &Impact::impulse, "j [N·s] on A along the normal");
  py::class_<ContactPointReport>(m, "ContactPoint",
                                 "A point where two bodies touched at the end of the last step, "
                                 "with what the contact solver pushed there.")
      .def_readonly("body_a", &ContactPointReport::body_a)
      .def_readonly("body_b", &ContactPointReport::body_b)
      .def_readonly("point", &ContactPointReport::point, "m, world")
      .def_readonly("normal", &ContactPointReport::normal, "unit, from B towards A")
      .def_readonly("normal_impulse", &ContactPointReport::normal_impulse,
                    "N·s on A along the normal over the last sub-step (≥ 0)")
      .def_readonly("tangent_impulse", &ContactPointReport::tangent_impulse,
                    "N·s on A along the normal turned a quarter turn counter-clockwise");
  py::class_<Space, std::unique_ptr<Space>>(
      m, "Space", "Owns the bodies and advances them in time (FR:Simulation-Space).")
      .def(py::init<const Settings&>(), py::arg("settings") = Settings{})
      .def("add_body", &Space::add_body, py::arg("body"),
           "Adds a body and returns its id (0, 1, ... in the order of adding).")
      .def(
          "step", [](Space& s, double dt) { on_engine_threads([&] { s.step(dt); }); },
          py::arg("dt"), "Advances by dt [s] > 0, on the threads of set_threads.")
      .def_property_readonly("time", &Space::time, "t [s]")
      .def_property_readonly("body_count", &Space::body_count)
      .def("name", [](const Space& s, BodyId id) { return std::string(s.name(id)); })
      .def("find_body", &Space::find_body, py::arg("name"),
           "The id of the body named `name` (not removed), or None.")
      .def("state", of_body(&Space::state), py::arg("body"),
           "Centre of mass, orientation in [0, 2π), velocities.")
      .def("mass", of_body(&Space::mass), py::arg("body"),
           "kg; inf for static and kinematic bodies")
      .def("moment", of_body(&Space::moment), py::arg("body"),
           "kg·m² about the centre of mass; inf if it cannot rotate")
      .def("set_position", by_body(&Space::set_position), py::arg("body"), py::arg("position"),
           "Moves the centre of mass to `position` [m].")
      .def("set_angle", by_body(&Space::set_angle), py::arg("body"), py::arg("angle"),
           "Turns the body to ϕ [rad] about its centre of mass.")
      .def("set_velocity", by_body(&Space::set_velocity), py::arg("body"), py::arg("velocity"),
           "Velocity of the centre of mass [m/s].")
      .def("set_angular_velocity", by_body(&Space::set_angular_velocity), py::arg("body"),
           py::arg("angular_velocity"), "ω [rad/s].")
      .def("apply_impulse", at_point(&Space::apply_impulse), py::arg("body"), py::arg("impulse"),
           py::arg("point") = std::nullopt,
           "Impulse J [N·s] at world point p [m] (default: the centre of mass): v changes by J/m "
           "(DD:impulseV), ω by (r × J)/I (DD:torque).")
      .def("apply_force", at_point(&Space::apply_force), py::arg("body"), py::arg("force"),
           py::arg("point") = std::nullopt,
           "Force F [N] at world point p [m] (default: the centre of mass) during the next step "
           "only, with torque r × F (DD:torque).")
      .def(
          "remove_body", [](Space& s, const BodyRef& body) { s.remove_body(id_of(s, body)); },
          py::arg("body"), "Removes the body: it no longer moves or collides; ids stay.")
      .def("removed", &Space::removed, py::arg("body"))
      .def("impacts", &Space::impacts,
           "The collisions resolved at their time of impact during the last step (IM:col2D).")
      .def("contact_points", &Space::contact_points,
           "The points of the contact constraints of the last sub-step, with the impulses the "
           "solver accumulated there: their normal impulses over the sub-step's length are the "
           "contact forces.")
      .def(
          "set_force_callback",
          [](Space& s, const BodyRef& body, std::function<Wrench(double, BodyId, BodyState)> f) {
            s.set_force_callback(id_of(s, body), [f](double t, BodyId j, const BodyState& st) {
              return f(t, j, st);
            });
          },
          py::arg("body"), py::arg("callback"),
          "callback(t, body, state) -> Wrench: a time-dependent force and torque.");
}

}  // namespace

void bind_space(py::module_& m) {
  bind_settings(m);
  bind_shapes(m);
  bind_bodies(m);
  bind_space_class(m);
}

}  // namespace gp::python
