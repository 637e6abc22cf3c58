// The dimensional audit against a hand analysis of the SRS's equations with the units of its
// table of symbols (srs/errata.md lists the reasoning for each failure), and the model functions
// themselves instantiated with units (verification/dimensions/code_audit.cpp).
#include <catch2/catch.hpp>
#include <set>

#include "gamephysics/models.hpp"
#include "verification/dimensions/dimensional_audit.hpp"
#include "verification/dimensions/si_quantities.hpp"
#include "verification/dimensions/unit_vector.hpp"

namespace {
namespace test_dimensional_audit {

TEST_CASE("Dimensional audit finds exactly the SRS's dimensional errors", "[dimensions]") {
  std::set<std::string> failing, written, code_failing;
  for (const auto& check : gp::verification::dimensional_audit()) {
    if (check.form == "as written") {
      written.insert(check.id);
      if (!check.consistent) failing.insert(check.id);
    } else if (!check.consistent) {
      code_failing.insert(check.id);
    }
  }
  CHECK(written.size() == 24);  // every TM, GD, DD and IM
  // By hand: u = dp/dt and θ = dϕ/dt equate a quantity with its rate; d̂ and n carry metres.
  CHECK(failing == std::set<std::string>{"DD:angDisp", "DD:linDisp", "GD:accelGravity",
                                         "GD:impulse", "IM:col2D", "TM:UniversalGravLaw"});
  CHECK(code_failing.empty());
}

TEST_CASE("Dimensional audit reports the dimensions on each side", "[dimensions]") {
  for (const auto& check : gp::verification::dimensional_audit()) {
    if (check.id == "DD:linDisp" && check.form == "as written") {
      CHECK(check.lhs_dimension == "m");
      CHECK(check.rhs_dimension == "m s^-1");
    }
    if (check.id == "GD:impulse" && check.form == "as written") {
      CHECK_THAT(check.rhs_dimension, Catch::StartsWith("inconsistent sum"));
    }
  }
}

TEST_CASE("Dimensional audit instantiates every model function with units", "[dimensions]") {
  std::set<std::string> functions, registered;
  for (const auto& r : gp::models::registrations()) registered.insert(r.function);
  for (const auto& check : gp::verification::dimensional_audit()) {
    if (check.form != "in the code") continue;
    functions.insert(check.equation);
    // Units by hand, from the doc comments: N·s, m, N·m and (m/s, m/s), in SI base units.
    if (check.id == "GD:impulse") CHECK(check.lhs_dimension == "m kg s^-1");
    if (check.id == "DD:linVel") CHECK(check.lhs_dimension == "(m, m)");
    if (check.id == "DD:torque") CHECK(check.lhs_dimension == "m^2 kg s^-2");
    if (check.id == "IM:col2D") CHECK(check.lhs_dimension == "(m s^-1, m s^-1)");
  }
  CHECK(functions == registered);
}

TEST_CASE("A model function gives the same numbers with units as with doubles", "[dimensions]") {
  // The same source, two instantiations: the elastic off-centre hit of tests/models.
  using namespace gp::verification;
  using namespace gp::verification::si_quantities;
  const gp::im::CollidingBody a{1.0 / 56.2, 1.0 / 74.5, {-2.51, 0.2}, 2.1, {-0.5, -0.5}};
  const gp::im::CollidingBody b{1.0 / 20.0, 1.0 / 3.0, {1.0, -0.5}, -1.0, {0.8, 0.4}};
  const gp::Vec2 n = gp::Vec2{1.0, 0.4}.normalized();
  const auto with_doubles = gp::im::collision_response(a, b, n, 0.8);
  const auto q = [](const gp::Vec2& x, auto unit) {
    using Q = decltype(unit);
    return UnitVec2<Q>{Q::from_value(x.x()), Q::from_value(x.y())};
  };
  using Body = gp::im::BasicCollidingBody<Inverse<Mass>, Inverse<Moment>, UnitVec2<Velocity>,
                                          AngularVelocity, UnitVec2<Length>>;
  const auto body = [&](const gp::im::CollidingBody& s) {
    return Body{Inverse<Mass>::from_value(s.inverse_mass),
                Inverse<Moment>::from_value(s.inverse_moment), q(s.velocity, Velocity()),
                AngularVelocity::from_value(s.angular_velocity), q(s.arm, Length())};
  };
  const auto with_units =
      gp::im::collision_response<Impulse, Body, UnitVec2<Dimensionless>, Dimensionless>(
          body(a), body(b), q(n, Dimensionless()), Dimensionless::from_value(0.8));
  REQUIRE(with_doubles.impulse > 0.0);
  CHECK(with_units.impulse.value() == with_doubles.impulse);
  CHECK(with_units.velocity_a.x.value() == with_doubles.velocity_a.x());
  CHECK(with_units.velocity_b.y.value() == with_doubles.velocity_b.y());
  CHECK(with_units.angular_velocity_a.value() == with_doubles.angular_velocity_a);
  CHECK(with_units.angular_velocity_b.value() == with_doubles.angular_velocity_b);
}

}  // namespace test_dimensional_audit
}  // namespace
