#include "verification/dimensions/dimensional_audit.hpp"

#include "verification/dimensions/code_audit.hpp"
#include "verification/dimensions/si_quantities.hpp"

namespace gp::verification {

namespace {

using namespace si_quantities;

// A right-hand side made of terms that must all share one dimension.
template <class First, class... Rest>
struct Terms {
  using first = First;
  static constexpr bool consistent = (same_dimension<First, Rest> && ...);
  static std::string dimension() {
    if constexpr (consistent) {
      return dimension_of<First>();
    } else {
      std::string text = "inconsistent sum: " + dimension_of<First>();
      ((text += " + " + dimension_of<Rest>()), ...);
      return text;
    }
  }
};

// An inconsistent sum has no dimension, so a product or quotient with it has none either.
template <class A, class B>
using Quotient = decltype(A() / B());

template <class Lhs, class Rhs>
DimensionalCheck check(std::string id, std::string form, std::string equation,
                       std::vector<SymbolUnit> symbols) {
  const bool consistent = Rhs::consistent && same_dimension<Lhs, typename Rhs::first>;
  return {std::move(id),       std::move(form),  std::move(equation), std::move(symbols),
          dimension_of<Lhs>(), Rhs::dimension(), consistent};
}

// GD:impulse is j = N / (D1 + D2): it is consistent when N/D1 and N/D2 share j's dimension.
// As written, ‖n‖ and ‖u_AP * n‖ are lengths (the SRS's table of symbols); the code's n is a
// dimensionless unit normal, so that u_AP × n is a length (code_audit.cpp).
using ImpulseNumeratorWritten = decltype(Velocity() * Length());
using ImpulseAsWritten =
    Terms<Quotient<ImpulseNumeratorWritten, decltype(Inverse<Mass>() * Squared<Length>())>,
          Quotient<ImpulseNumeratorWritten, Quotient<Squared<Length>, Moment>>>;

}  // namespace

std::vector<DimensionalCheck> dimensional_audit() {
  const std::string written = "as written";
  std::vector<DimensionalCheck> checks{
      check<Force, Terms<decltype(Mass() * Acceleration())>>(
          "TM:NewtonSecLawMot", written, "F = m a", {{"F", "N"}, {"m", "kg"}, {"a", "m/s^2"}}),
      check<Force, Terms<Force>>("TM:NewtonThirdLawMot", written, "F1 = -F2",
                                 {{"F1", "N"}, {"F2", "N"}}),
      check<Force, Terms<decltype(GravitationalConstant() * Mass() * Mass() / Squared<Length>() *
                                  Length())>>("TM:UniversalGravLaw", written,
                                              "F_g = G m1 m2 / |d|^2 * d_hat",
                                              {{"F_g", "N"},
                                               {"G", "m^3/(kg*s^2)"},
                                               {"m1", "kg"},
                                               {"m2", "kg"},
                                               {"d", "m"},
                                               {"d_hat", "m"}}),
      check<Torque, Terms<decltype(Moment() * AngularAcceleration())>>(
          "TM:NewtonSecLawRotMot", written, "tau = I alpha",
          {{"tau", "N*m"}, {"I", "kg*m^2"}, {"alpha", "rad/s^2"}}),
      check<Acceleration,
            Terms<decltype(GravitationalConstant() * Mass() / Squared<Length>() * Length())>>(
          "GD:accelGravity", written, "g = -G M / |d|^2 * d_hat",
          {{"g", "m/s^2"}, {"G", "m^3/(kg*s^2)"}, {"M", "kg"}, {"d", "m"}, {"d_hat", "m"}}),
      check<Impulse, ImpulseAsWritten>(
          "GD:impulse", written,
          "j = -(1 + C_R) v_i^AB . n / ((1/m_A + 1/m_B) |n|^2 + |u_AP * n|^2 / I_A + ...)",
          {{"j", "N*s"},
           {"C_R", "1"},
           {"v_i^AB", "m/s"},
           {"n", "m"},
           {"m_A", "kg"},
           {"|u_AP * n|", "m"},
           {"I_A", "kg*m^2"}}),
      check<Length, Terms<decltype(Mass() * Length() / Mass())>>(
          "DD:ctrOfMass", written, "p_CM = sum(m_j p_j) / m_T",
          {{"p_CM", "m"}, {"m_j", "kg"}, {"p_j", "m"}, {"m_T", "kg"}}),
      check<Length, Terms<Rate<Length>>>("DD:linDisp", written, "u = dp/dt",
                                         {{"u", "m"}, {"p", "m"}, {"t", "s"}}),
      check<Velocity, Terms<Rate<Length>>>("DD:linVel", written, "v = du/dt",
                                           {{"v", "m/s"}, {"u", "m"}, {"t", "s"}}),
      check<Acceleration, Terms<Rate<Velocity>>>("DD:linAcc", written, "a = dv/dt",
                                                 {{"a", "m/s^2"}, {"v", "m/s"}, {"t", "s"}}),
      check<Angle, Terms<Rate<Angle>>>("DD:angDisp", written, "theta = dphi/dt",
                                       {{"theta", "rad"}, {"phi", "rad"}, {"t", "s"}}),
      check<AngularVelocity, Terms<Rate<Angle>>>(
          "DD:angVel", written, "omega = dtheta/dt",
          {{"omega", "rad/s"}, {"theta", "rad"}, {"t", "s"}}),
      check<AngularAcceleration, Terms<Rate<AngularVelocity>>>(
          "DD:angAccel", written, "alpha = domega/dt",
          {{"alpha", "rad/s^2"}, {"omega", "rad/s"}, {"t", "s"}}),
      check<Velocity, Terms<Velocity, decltype(AngularVelocity() * Length())>>(
          "DD:chaslesThm", written, "v_B = v_O + omega x u_OB",
          {{"v_B", "m/s"}, {"v_O", "m/s"}, {"omega", "rad/s"}, {"u_OB", "m"}}),
      check<Torque, Terms<decltype(Length() * Force())>>("DD:torque", written, "tau = r x F",
                                                         {{"tau", "N*m"}, {"r", "m"}, {"F", "N"}}),
      check<Energy, Terms<decltype(Mass() * Squared<Velocity>())>>(
          "DD:kEnergy", written, "KE = m |v|^2 / 2", {{"KE", "J"}, {"m", "kg"}, {"v", "m/s"}}),
      check<Dimensionless, Terms<decltype(Velocity() * Length() / (Velocity() * Length()))>>(
          "DD:coeffRestitution", written, "C_R = -(v_f^AB . n) / (v_i^AB . n)",
          {{"C_R", "1"}, {"v_f^AB", "m/s"}, {"v_i^AB", "m/s"}, {"n", "m"}}),
      check<Velocity, Terms<Velocity, Velocity>>(
          "DD:reVeInColl", written, "v_i^AB = v^AP - v^BP",
          {{"v_i^AB", "m/s"}, {"v^AP", "m/s"}, {"v^BP", "m/s"}}),
      check<Impulse, Terms<decltype(Mass() * Velocity())>>(
          "DD:impulseV", written, "J = m dv", {{"J", "N*s"}, {"m", "kg"}, {"dv", "m/s"}}),
      check<Energy, Terms<decltype(Mass() * Acceleration() * Length())>>(
          "DD:potEnergy", written, "PE = m g h",
          {{"PE", "J"}, {"m", "kg"}, {"g", "m/s^2"}, {"h", "m"}}),
      check<Moment, Terms<decltype(Mass() * Squared<Length>())>>(
          "DD:momentOfInertia", written, "I = sum(m_j d_j^2)",
          {{"I", "kg*m^2"}, {"m_j", "kg"}, {"d_j", "m"}}),
      check<Acceleration, Terms<Acceleration, decltype(Force() / Mass())>>(
          "IM:transMot", written, "a_j = g + F_j / m_j",
          {{"a_j", "m/s^2"}, {"g", "m/s^2"}, {"F_j", "N"}, {"m_j", "kg"}}),
      check<AngularAcceleration, Terms<decltype(Torque() / Moment())>>(
          "IM:rotMot", written, "alpha_j = tau_j / I",
          {{"alpha_j", "rad/s^2"}, {"tau_j", "N*m"}, {"I", "kg*m^2"}}),
      check<Velocity, Terms<Velocity, decltype(Impulse() / Mass() * Length())>>(
          "IM:col2D", written, "v_A(t_c) = v_A(t) + j / m_A * n",
          {{"v_A", "m/s"}, {"j", "N*s"}, {"m_A", "kg"}, {"n", "m"}}),
  };
  for (auto& check : code_dimensional_audit()) checks.push_back(std::move(check));
  return checks;
}

}  // namespace gp::verification
