// Lift-offs in the event-driven oracle: a contact whose normal force falls through zero must let
// go, never pull. Checked by conservation (a box leaving a step's corner keeps its energy), by
// Newton's second law read back from the trajectory (a frictionless disc resting on another is
// only ever pushed), against the time-stepping reference, and at the guard that turns a pulling
// active contact into an error.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "oracle_scenes.hpp"
#include "scene/scene.hpp"
#include "verification/oracle/hybrid/contact_events.hpp"
#include "verification/oracle/model/world.hpp"
#include "verification/oracle/oracle.hpp"

using gp::Vec2;
using gp::verification::OracleDomainError;
using gp::verification::OracleMethod;
using gp::verification::OracleOptions;
using gp::verification::OracleResult;
using gp::verification::run_oracle;

using gp::test::with;

namespace {
namespace test_oracle_lift_off {

constexpr double kG = 9.81;
constexpr double kRadius = 0.5;

// Three frictionless discs (C_R = 0) dropped into a box 4 m wide: the top one strikes the other
// two, rides on the right one and leaves it before it lands.
gp::Scene three_discs() {
  return gp::test::scene_of(gp::test::with_gravity(kG),
                            {gp::test::open_box(2.0, 10.0, 0.0),
                             gp::test::disc("left", {-0.6, 1.0}, Vec2::Zero(), kRadius, 1.0, 0.0),
                             gp::test::disc("right", {0.5, 2.2}, Vec2::Zero(), kRadius, 1.0, 0.0),
                             gp::test::disc("top", {-0.1, 3.5}, Vec2::Zero(), kRadius, 1.0, 0.0)});
}

constexpr std::size_t kRight = 2;
constexpr std::size_t kTop = 3;

TEST_CASE("oracle: a box leaving a step's corner never gains energy", "[oracle][contact]") {
  // step_tip has no impact: the box turns about the corner, slips, and lets go. With a static
  // step, friction can only take energy away, so E = ½ m v² + ½ I ω² + m g y never rises.
  // Missing the lift-off once left the contact sliding with a negative normal force, whose
  // friction pushed: +0.012 J between 0.465 and 0.5 s.
  const gp::Scene scene = gp::load_scene(std::string(GP_SOURCE_DIR) + "/scenes/step_tip.json");
  const double mass = 1.0, moment = 1.0 / 6.0;  // the unit box of 1 kg/m²: m (w² + h²) / 12
  std::vector<double> times;
  for (int k = 0; k <= 100; ++k) times.push_back(0.005 * k);
  for (OracleMethod method :
       {OracleMethod::CvodeAdams, OracleMethod::CvodeBdf, OracleMethod::ArkodeErk}) {
    INFO("method " << gp::verification::oracle_method_name(method));
    const OracleResult r = run_oracle(scene, times, with(method));
    REQUIRE(r.events.empty());
    double previous = INFINITY;
    for (std::size_t k = 0; k < times.size(); ++k) {
      const gp::BodyState& s = r.states[k][1];
      const double energy = 0.5 * mass * s.velocity.squaredNorm() +
                            0.5 * moment * s.angular_velocity * s.angular_velocity +
                            mass * kG * s.position.y();
      INFO("t = " << times[k]);
      // 1e-10 J: the solver's error on 4.9 J at tolerances of 1e-12.
      CHECK(energy <= previous + 1e-10);
      previous = energy;
    }
  }
}

TEST_CASE("oracle: a frictionless disc resting on another is pushed, never pulled",
          "[oracle][contact]") {
  // Newton's second law read back from the trajectory: while the top disc touches only the right
  // one, m (a − g) is the contact's force, along n from the right disc's centre to the top's, and
  // its component along n must be ≥ 0. a by central differences over ±δ, away from impacts.
  const gp::Scene scene = three_discs();
  const double delta = 1e-4;
  std::vector<double> centres;
  for (int k = 0; k <= 190; ++k) centres.push_back(0.68 + 0.002 * k);  // to 1.06 s, before landing
  std::vector<double> times;
  for (double t : centres) {
    times.insert(times.end(), {t - delta, t, t + delta});
  }
  const OracleResult r = run_oracle(scene, times);
  int touching = 0;
  double least = INFINITY;
  for (std::size_t k = 0; k < centres.size(); ++k) {
    const double t = centres[k];
    const bool impact = std::any_of(r.events.begin(), r.events.end(),
                                    [&](const auto& e) { return std::abs(e.time - t) <= delta; });
    if (impact) continue;
    const gp::BodyState& top = r.states[3 * k + 1][kTop];
    const gp::BodyState& right = r.states[3 * k + 1][kRight];
    const Vec2 between = top.position - right.position;
    if (between.norm() - 2.0 * kRadius > 1e-9) continue;
    ++touching;
    const Vec2 a =
        (r.states[3 * k + 2][kTop].velocity - r.states[3 * k][kTop].velocity) / (2.0 * delta);
    const double pushed = (a - Vec2(0.0, -kG)).dot(between.normalized());
    least = std::min(least, pushed);
    INFO("t = " << t << ": contact force / m along n = " << pushed << " m/s²");
    // 1e-4 m/s²: the central difference's error, δ² ȧ̇ / 6 plus 1e-12 m/s of round-off / δ.
    CHECK(pushed >= -1e-4);
  }
  INFO("least force / m " << least);
  // It rides on the right disc for a while after the impact at 0.675 s (measured: from 0.68 to
  // 0.86 s, 92 instants).
  CHECK(touching >= 50);
}

TEST_CASE("oracle: the top disc's landing speed agrees with time-stepping",
          "[oracle][contact][stepping]") {
  // The reference: Moreau–Jean time-stepping, which lets the top disc go at the velocity level
  // without any lift-off event. Just before it lands (at 1.068 s) the two agree within the
  // stepping's first-order error. Held by the missed lift-off, the top disc reached there
  // 0.7 m/s slower.
  const gp::Scene scene = three_discs();
  const std::vector<double> times{1.06};
  const Vec2 v = run_oracle(scene, times).states[0][kTop].velocity;
  for (const double h : {1e-3, 5e-4, 2.5e-4}) {
    OracleOptions stepping = with(OracleMethod::TimeStepping);
    stepping.step = h;
    const Vec2 stepped = run_oracle(scene, times, stepping).states[0][kTop].velocity;
    INFO("h = " << h << ": |Δv| = " << (stepped - v).norm() << " m/s");
    // 30 h: measured 5.3, 25 and 8.8 h; not monotone, because the top disc's impact on the right
    // one, as that one lands (0.675 s), falls inside a step at a place that varies with h.
    CHECK((stepped - v).norm() <= 30.0 * h);
  }
}

TEST_CASE("oracle: an active contact that pulls is an error, never silent", "[oracle][contact]") {
  // A disc of 1 kg touching the ground under gravity g upwards: held at g̈ = 0, the contact
  // would pull with f_n = −m g. The guard at every stop of the solver refuses it; with gravity
  // downwards it pushes with m g and passes.
  for (const bool upwards : {false, true}) {
    const gp::Scene scene = gp::test::scene_of(
        gp::test::with_gravity(upwards ? -kG : kG),
        {gp::test::ground(0.0),
         gp::test::disc("disc", {0.0, kRadius}, Vec2::Zero(), kRadius, 1.0, 0.0)});
    const gp::oracle::World world = gp::oracle::build_world(scene);
    gp::oracle::HybridSystem system(world);
    gp::oracle::EventWatch watch(world, 1e-9, 1e-9);
    const gp::verification::OracleOptions options;
    gp::oracle::ContactEvents contacts(system, watch, options);
    const std::vector<gp::oracle::Motion> motions{world.bodies[0].initial, world.bodies[1].initial};
    const auto geometry =
        gp::oracle::contact_geometry(world.bodies[0].hulls[0], {motions[0].position, 0.0},
                                     world.bodies[1].hulls[0], {motions[1].position, 0.0}, 1e-9);
    REQUIRE(geometry.points.size() == 1);
    REQUIRE(watch.pairs().size() == 1);
    system.set_contacts(
        {gp::oracle::make_active_contact(world, watch.pairs()[0], 0, geometry.points[0].feature)});
    gp::oracle::Snapshot snapshot;
    system.evaluate(0.0, motions, snapshot);
    INFO("gravity " << (upwards ? "upwards" : "downwards"));
    CHECK(snapshot.forces[0].normal == Approx(upwards ? -kG : kG).epsilon(1e-12));
    if (upwards) {
      CHECK_THROWS_AS(contacts.require_pushing(snapshot), OracleDomainError);
    } else {
      CHECK_NOTHROW(contacts.require_pushing(snapshot));
    }
  }
}

}  // namespace test_oracle_lift_off
}  // namespace
