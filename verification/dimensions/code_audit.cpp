#include "verification/dimensions/code_audit.hpp"

#include <array>
#include <span>

#include "gamephysics/models.hpp"
#include "verification/dimensions/si_quantities.hpp"
#include "verification/dimensions/unit_vector.hpp"

namespace gp::verification {

namespace {

using namespace si_quantities;
template <class X>
using V = UnitVec2<X>;

template <class X>
X q(double value) {
  return X::from_value(value);
}
template <class X>
V<X> v(double x, double y) {
  return {q<X>(x), q<X>(y)};
}

template <class T>
struct Component {
  using type = T;
};
template <class X>
struct Component<UnitVec2<X>> {
  using type = X;
};
template <class T>
struct Component<std::span<const T>> : Component<T> {};

template <class T>
std::string unit_text() {
  const std::string unit = dimension_of<typename Component<T>::type>();
  return is_unit_vector<T> ? "(" + unit + ", " + unit + ")" : unit;
}

// The row of one instantiated model function: `names` are its result's, then its parameters'.
template <class Result, class... Args>
DimensionalCheck row(std::string id, std::string function, std::vector<std::string> names,
                     const Result&, const Args&...) {
  const std::array<std::string, sizeof...(Args)> units{unit_text<Args>()...};
  std::vector<SymbolUnit> symbols{{names.at(0), unit_text<Result>()}};
  for (std::size_t i = 0; i < units.size(); ++i) symbols.push_back({names.at(i + 1), units[i]});
  return {std::move(id),
          "in the code",
          std::move(function),
          std::move(symbols),
          unit_text<Result>(),
          unit_text<Result>(),
          true};
}

}  // namespace

std::vector<DimensionalCheck> code_dimensional_audit() {
  // Values are the SRS's reasonable ones where it gives them; only their units matter here.
  const auto m = q<Mass>(56.2);
  const auto h = q<Time>(0.016);
  const auto I = q<Moment>(74.5);
  const auto omega = q<AngularVelocity>(2.1);
  const auto phi = q<Angle>(1.5);
  const auto F = v<Force>(98.1, 0.0);
  const auto p = v<Length>(0.412, 0.3);
  const auto vel = v<Velocity>(2.51, -1.0);
  const auto g = v<Acceleration>(0.0, -9.81);
  const auto G = q<GravitationalConstant>(6.6743e-11);
  const auto n = v<Dimensionless>(0.0, 1.0);
  const auto cr = q<Dimensionless>(0.8);
  const auto tau = q<Torque>(200.0);
  const auto alpha = q<AngularAcceleration>(2.7);
  const auto inverse_mass = q<Inverse<Mass>>(1.0 / 56.2);
  const auto inverse_moment = q<Inverse<Moment>>(0.01);
  const std::array masses{m, m};
  const std::array positions{p, -p};
  const std::span<const Mass> ms(masses);
  const std::span<const V<Length>> ps(positions);
  using Body = im::BasicCollidingBody<Inverse<Mass>, Inverse<Moment>, V<Velocity>, AngularVelocity,
                                      V<Length>>;
  const Body a{inverse_mass, inverse_moment, vel, omega, p};
  const Body b{inverse_mass, inverse_moment, -vel, -omega, -p};
  const auto response =
      im::collision_response<Impulse, Body, V<Dimensionless>, Dimensionless>(a, b, n, cr);
  const auto J = v<Impulse>(1.0, 2.0);
  return {
      row("TM:NewtonSecLawMot", "gp::tm::acceleration_from_force", {"a", "F", "m"},
          tm::acceleration_from_force<V<Acceleration>, V<Force>, Mass>(F, m), F, m),
      row("TM:NewtonThirdLawMot", "gp::tm::reaction_force", {"F2", "F1"},
          tm::reaction_force<V<Force>>(F), F),
      row("TM:UniversalGravLaw", "gp::tm::gravitational_force", {"F_g", "G", "m1", "m2", "d"},
          tm::gravitational_force<V<Force>, GravitationalConstant, Mass, V<Length>>(G, m, m, p), G,
          m, m, p),
      row("TM:NewtonSecLawRotMot", "gp::tm::angular_acceleration_from_torque",
          {"alpha", "tau", "I"},
          tm::angular_acceleration_from_torque<AngularAcceleration, Torque, Moment>(tau, I), tau,
          I),
      row("GD:accelGravity", "gp::gd::gravitational_acceleration", {"g", "G", "M", "d"},
          gd::gravitational_acceleration<V<Acceleration>, GravitationalConstant, Mass, V<Length>>(
              G, m, p),
          G, m, p),
      row("GD:impulse", "gp::gd::collision_impulse",
          {"j", "C_R", "v_i^AB", "n", "1/m_A", "1/m_B", "1/I_A", "1/I_B", "u_AP", "u_BP"},
          gd::collision_impulse<Impulse, Dimensionless, V<Velocity>, V<Dimensionless>,
                                Inverse<Mass>, Inverse<Moment>, V<Length>>(
              cr, vel, n, inverse_mass, inverse_mass, inverse_moment, inverse_moment, p, -p),
          cr, vel, n, inverse_mass, inverse_mass, inverse_moment, inverse_moment, p, p),
      row("DD:ctrOfMass", "gp::dd::center_of_mass", {"p_CM", "m_j", "p_j"},
          dd::center_of_mass<V<Length>, Mass>(ms, ps), ms, ps),
      row("DD:linDisp", "gp::dd::displaced_position", {"p(t)", "p(t0)", "u"},
          dd::displaced_position<V<Length>>(p, p), p, p),
      row("DD:linVel", "gp::dd::displacement_from_velocity", {"u", "v", "h"},
          dd::displacement_from_velocity<V<Length>, V<Velocity>, Time>(vel, h), vel, h),
      row("DD:linAcc", "gp::dd::velocity_change_from_acceleration", {"dv", "a", "h"},
          dd::velocity_change_from_acceleration<V<Velocity>, V<Acceleration>, Time>(g, h), g, h),
      row("DD:angDisp", "gp::dd::rotated_orientation", {"phi(t)", "phi(t0)", "theta"},
          dd::rotated_orientation<Angle>(phi, phi), phi, phi),
      row("DD:angVel", "gp::dd::angular_displacement_from_velocity", {"theta", "omega", "h"},
          dd::angular_displacement_from_velocity<Angle, AngularVelocity, Time>(omega, h), omega, h),
      row("DD:angAccel", "gp::dd::angular_velocity_change_from_acceleration",
          {"domega", "alpha", "h"},
          dd::angular_velocity_change_from_acceleration<AngularVelocity, AngularAcceleration, Time>(
              alpha, h),
          alpha, h),
      row("DD:chaslesThm", "gp::dd::point_velocity", {"v_B", "v_O", "omega", "u_OB"},
          dd::point_velocity<V<Velocity>, AngularVelocity, V<Length>>(vel, omega, p), vel, omega,
          p),
      row("DD:torque", "gp::dd::torque", {"tau", "r", "F"},
          dd::torque<Torque, V<Length>, V<Force>>(p, F), p, F),
      row("DD:kEnergy", "gp::dd::kinetic_energy", {"KE", "m", "v", "I", "omega"},
          dd::kinetic_energy<Energy, Mass, V<Velocity>, Moment, AngularVelocity>(m, vel, I, omega),
          m, vel, I, omega),
      row("DD:coeffRestitution", "gp::dd::coefficient_of_restitution",
          {"C_R", "v_f^AB", "v_i^AB", "n"},
          dd::coefficient_of_restitution<Dimensionless, V<Velocity>, V<Dimensionless>>(-vel, vel,
                                                                                       n),
          vel, vel, n),
      row("DD:reVeInColl", "gp::dd::relative_velocity", {"v_i^AB", "v^AP", "v^BP"},
          dd::relative_velocity<V<Velocity>>(vel, -vel), vel, vel),
      row("DD:impulseV", "gp::dd::velocity_change_from_impulse", {"dv", "J", "1/m"},
          dd::velocity_change_from_impulse<V<Velocity>, V<Impulse>, Inverse<Mass>>(J, inverse_mass),
          J, inverse_mass),
      row("DD:potEnergy", "gp::dd::potential_energy", {"PE", "m", "g", "p"},
          dd::potential_energy<Energy, Mass, V<Acceleration>, V<Length>>(m, g, p), m, g, p),
      row("DD:momentOfInertia", "gp::dd::moment_of_inertia", {"I", "m_j", "p_j", "axis"},
          dd::moment_of_inertia<Moment, Mass, V<Length>>(ms, ps, p), ms, ps, p),
      row("IM:transMot", "gp::im::translational_acceleration", {"a_j", "g", "F_j", "m_j"},
          im::translational_acceleration<V<Acceleration>, V<Force>, Mass>(g, F, m), g, F, m),
      row("IM:rotMot", "gp::im::angular_acceleration", {"alpha_j", "tau_j", "I"},
          im::angular_acceleration<AngularAcceleration, Torque, Moment>(tau, I), tau, I),
      row("IM:col2D", "gp::im::collision_response",
          {"v_A(t_c+)", "v_A", "omega_A", "u_AP", "1/m_A", "1/I_A", "n", "C_R"},
          response.velocity_a, a.velocity, a.angular_velocity, a.arm, a.inverse_mass,
          a.inverse_moment, n, cr),
  };
}

}  // namespace gp::verification
