// The SRS model functions for Python: gamephysics.models.tm, .gd, .dd and .im, one function each,
// calling the C++ one (not a copy of it). Each docstring is the C++ doc comment, with its SRS id,
// equation and units, generated from the model headers (python/model_docs.py).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "bindings.hpp"
#include "gamephysics/models.hpp"
#include "python/model_docs.hpp"

namespace py = pybind11;

namespace gp::python {

namespace {

/// The doc comment of model function `name` ("dd::kinetic_energy").
const char* doc(std::string_view name) {
  for (const auto& [function, text] : kModelDocs) {
    if (function == name) return text.data();
  }
  throw std::logic_error("no doc comment for model function " + std::string(name));
}

void bind_tm(py::module_& tm) {
  tm.def(
      "acceleration_from_force",
      [](const Vec2& force, double mass) { return gp::tm::acceleration_from_force(force, mass); },
      py::arg("force"), py::arg("mass"), doc("tm::acceleration_from_force"));
  tm.def(
      "angular_acceleration_from_torque",
      [](double torque, double moment) {
        return gp::tm::angular_acceleration_from_torque(torque, moment);
      },
      py::arg("torque"), py::arg("moment"), doc("tm::angular_acceleration_from_torque"));
  tm.def(
      "reaction_force", [](const Vec2& force) { return gp::tm::reaction_force(force); },
      py::arg("force"), doc("tm::reaction_force"));
  tm.def(
      "gravitational_force",
      [](double G, double mass1, double mass2, const Vec2& distance) {
        return gp::tm::gravitational_force(G, mass1, mass2, distance);
      },
      py::arg("G"), py::arg("mass1"), py::arg("mass2"), py::arg("distance"),
      doc("tm::gravitational_force"));
}

void bind_gd(py::module_& gd) {
  gd.def(
      "collision_impulse",
      [](double restitution, const Vec2& relative_velocity, const Vec2& normal,
         double inverse_mass_a, double inverse_mass_b, double inverse_moment_a,
         double inverse_moment_b, const Vec2& arm_a, const Vec2& arm_b) {
        return gp::gd::collision_impulse(restitution, relative_velocity, normal, inverse_mass_a,
                                         inverse_mass_b, inverse_moment_a, inverse_moment_b, arm_a,
                                         arm_b);
      },
      py::arg("restitution"), py::arg("relative_velocity"), py::arg("normal"),
      py::arg("inverse_mass_a"), py::arg("inverse_mass_b"), py::arg("inverse_moment_a"),
      py::arg("inverse_moment_b"), py::arg("arm_a"), py::arg("arm_b"),
      doc("gd::collision_impulse"));
  gd.def(
      "gravitational_acceleration",
      [](double G, double mass, const Vec2& distance) {
        return gp::gd::gravitational_acceleration(G, mass, distance);
      },
      py::arg("G"), py::arg("mass"), py::arg("distance"), doc("gd::gravitational_acceleration"));
}

void bind_dd_kinematics(py::module_& dd) {
  dd.def(
      "angular_velocity_change_from_acceleration",
      [](double mean_angular_acceleration, double step) {
        return gp::dd::angular_velocity_change_from_acceleration(mean_angular_acceleration, step);
      },
      py::arg("mean_angular_acceleration"), py::arg("step"),
      doc("dd::angular_velocity_change_from_acceleration"));
  dd.def(
      "rotated_orientation",
      [](double orientation, double angular_displacement) {
        return gp::dd::rotated_orientation(orientation, angular_displacement);
      },
      py::arg("orientation"), py::arg("angular_displacement"), doc("dd::rotated_orientation"));
  dd.def(
      "angular_displacement_from_velocity",
      [](double mean_angular_velocity, double step) {
        return gp::dd::angular_displacement_from_velocity(mean_angular_velocity, step);
      },
      py::arg("mean_angular_velocity"), py::arg("step"),
      doc("dd::angular_displacement_from_velocity"));
  dd.def(
      "velocity_change_from_acceleration",
      [](const Vec2& mean_acceleration, double step) {
        return gp::dd::velocity_change_from_acceleration(mean_acceleration, step);
      },
      py::arg("mean_acceleration"), py::arg("step"), doc("dd::velocity_change_from_acceleration"));
  dd.def(
      "displaced_position",
      [](const Vec2& position, const Vec2& displacement) {
        return gp::dd::displaced_position(position, displacement);
      },
      py::arg("position"), py::arg("displacement"), doc("dd::displaced_position"));
  dd.def(
      "displacement_from_velocity",
      [](const Vec2& mean_velocity, double step) {
        return gp::dd::displacement_from_velocity(mean_velocity, step);
      },
      py::arg("mean_velocity"), py::arg("step"), doc("dd::displacement_from_velocity"));
  dd.def(
      "point_velocity",
      [](const Vec2& velocity_origin, double angular_velocity, const Vec2& offset) {
        return gp::dd::point_velocity(velocity_origin, angular_velocity, offset);
      },
      py::arg("velocity_origin"), py::arg("angular_velocity"), py::arg("offset"),
      doc("dd::point_velocity"));
  dd.def(
      "relative_velocity",
      [](const Vec2& velocity_a_at_contact, const Vec2& velocity_b_at_contact) {
        return gp::dd::relative_velocity(velocity_a_at_contact, velocity_b_at_contact);
      },
      py::arg("velocity_a_at_contact"), py::arg("velocity_b_at_contact"),
      doc("dd::relative_velocity"));
}

void bind_dd_dynamics(py::module_& dd) {
  dd.def(
      "center_of_mass",
      [](const std::vector<double>& masses, const std::vector<Vec2>& positions) {
        if (masses.size() != positions.size()) {
          throw std::invalid_argument("center_of_mass: as many positions as masses");
        }
        return gp::dd::center_of_mass(masses, positions);
      },
      py::arg("masses"), py::arg("positions"), doc("dd::center_of_mass"));
  dd.def(
      "moment_of_inertia",
      [](const std::vector<double>& masses, const std::vector<Vec2>& positions, const Vec2& axis) {
        if (masses.size() != positions.size()) {
          throw std::invalid_argument("moment_of_inertia: as many positions as masses");
        }
        return gp::dd::moment_of_inertia(masses, positions, axis);
      },
      py::arg("masses"), py::arg("positions"), py::arg("axis"), doc("dd::moment_of_inertia"));
  dd.def(
      "coefficient_of_restitution",
      [](const Vec2& final_relative_velocity, const Vec2& initial_relative_velocity,
         const Vec2& normal) {
        return gp::dd::coefficient_of_restitution(final_relative_velocity,
                                                  initial_relative_velocity, normal);
      },
      py::arg("final_relative_velocity"), py::arg("initial_relative_velocity"), py::arg("normal"),
      doc("dd::coefficient_of_restitution"));
  dd.def(
      "velocity_change_from_impulse",
      [](const Vec2& impulse, double inverse_mass) {
        return gp::dd::velocity_change_from_impulse(impulse, inverse_mass);
      },
      py::arg("impulse"), py::arg("inverse_mass"), doc("dd::velocity_change_from_impulse"));
  dd.def(
      "kinetic_energy",
      [](double mass, const Vec2& velocity, double moment, double angular_velocity) {
        return gp::dd::kinetic_energy(mass, velocity, moment, angular_velocity);
      },
      py::arg("mass"), py::arg("velocity"), py::arg("moment") = 0.0,
      py::arg("angular_velocity") = 0.0, doc("dd::kinetic_energy"));
  dd.def(
      "potential_energy",
      [](double mass, const Vec2& gravity, const Vec2& position) {
        return gp::dd::potential_energy(mass, gravity, position);
      },
      py::arg("mass"), py::arg("gravity"), py::arg("position"), doc("dd::potential_energy"));
  dd.def(
      "torque", [](const Vec2& arm, const Vec2& force) { return gp::dd::torque(arm, force); },
      py::arg("arm"), py::arg("force"), doc("dd::torque"));
}

void bind_im(py::module_& im) {
  py::class_<gp::im::CollidingBody>(im, "CollidingBody",
                                    "One of the two bodies of a collision, at t_c.")
      .def(py::init([](double inverse_mass, double inverse_moment, const Vec2& velocity,
                       double angular_velocity, const Vec2& arm) {
             return gp::im::CollidingBody{inverse_mass, inverse_moment, velocity, angular_velocity,
                                          arm};
           }),
           py::arg("inverse_mass"), py::arg("inverse_moment"), py::arg("velocity"),
           py::arg("angular_velocity"), py::arg("arm"))
      .def_readwrite("inverse_mass", &gp::im::CollidingBody::inverse_mass, "1/m [1/kg]")
      .def_readwrite("inverse_moment", &gp::im::CollidingBody::inverse_moment, "1/I [1/(kg·m²)]")
      .def_readwrite("velocity", &gp::im::CollidingBody::velocity, "v [m/s]")
      .def_readwrite("angular_velocity", &gp::im::CollidingBody::angular_velocity, "ω [rad/s]")
      .def_readwrite("arm", &gp::im::CollidingBody::arm, "u_P [m]");
  py::class_<gp::im::CollisionResponse>(im, "CollisionResponse",
                                        "Velocities just after a collision, and the impulse.")
      .def_readonly("velocity_a", &gp::im::CollisionResponse::velocity_a, "m/s")
      .def_readonly("angular_velocity_a", &gp::im::CollisionResponse::angular_velocity_a, "rad/s")
      .def_readonly("velocity_b", &gp::im::CollisionResponse::velocity_b, "m/s")
      .def_readonly("angular_velocity_b", &gp::im::CollisionResponse::angular_velocity_b, "rad/s")
      .def_readonly("impulse", &gp::im::CollisionResponse::impulse, "j [N·s]");
  im.def(
      "collision_response",
      [](const gp::im::CollidingBody& a, const gp::im::CollidingBody& b, const Vec2& normal,
         double restitution) { return gp::im::collision_response(a, b, normal, restitution); },
      py::arg("a"), py::arg("b"), py::arg("normal"), py::arg("restitution"),
      doc("im::collision_response"));
  im.def(
      "angular_acceleration",
      [](double torque, double moment) { return gp::im::angular_acceleration(torque, moment); },
      py::arg("torque"), py::arg("moment"), doc("im::angular_acceleration"));
  im.def(
      "translational_acceleration",
      [](const Vec2& gravity, const Vec2& force, double mass) {
        return gp::im::translational_acceleration(gravity, force, mass);
      },
      py::arg("gravity"), py::arg("force"), py::arg("mass"), doc("im::translational_acceleration"));
}

}  // namespace

void bind_models(py::module_& m) {
  py::module_ models = m.def_submodule("models", "The SRS's models, one function each.");
  py::module_ tm = models.def_submodule("tm", "TM: the SRS's theoretical models.");
  py::module_ gd = models.def_submodule("gd", "GD: the SRS's general definitions.");
  py::module_ dd = models.def_submodule("dd", "DD: the SRS's data definitions.");
  py::module_ im = models.def_submodule("im", "IM: the SRS's instance models.");
  bind_tm(tm);
  bind_gd(gd);
  bind_dd_kinematics(dd);
  bind_dd_dynamics(dd);
  bind_im(im);
}

}  // namespace gp::python
