// The SUNDIALS oracle against closed forms: free flight, constant torque, a circular orbit,
// head-on, oblique and off-centre elastic impacts, a kinematic paddle, a bouncing ball and a ball
// coming to rest, each within 1e-9 relative with every method; CVODE and ARKODE against each
// other; a spinning disc landing on a frictional floor; and the scenes outside the oracle's
// domain (an overlap at the start, solver failure), which must end quickly with OracleDomainError.
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "check_near.hpp"
#include "engine/scene/scene_space.hpp"
#include "gamephysics/gamephysics.hpp"
#include "gamephysics/models/dd/kinetic_energy.hpp"
#include "oracle_scenes.hpp"
#include "verification/oracle/oracle.hpp"
#include "verification/oracle_csv.hpp"

using gp::Vec2;
using gp::verification::OracleDomainError;
using gp::verification::OracleMethod;
using gp::verification::OracleOptions;
using gp::verification::OracleResult;
using gp::verification::run_oracle;

using gp::test::check_near;
using gp::test::disc;
using gp::test::ground;
using gp::test::scene_of;
using gp::test::with_gravity;

namespace {
namespace test_oracle {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

OracleOptions tight(OracleMethod method, double tolerance = 1e-12) {
  OracleOptions options;
  options.method = method;
  options.rtol = tolerance;
  options.atol = tolerance;
  return options;
}

// The solvers bound the error of each step; over the 200 (Adams) to 6000 (ERK) steps of a period
// of the orbit, or of a fall sharpening as 1/r², the error adds up to about 1e3 rtol, so the
// scenes with gravitation ask for 1e-14.
constexpr double kGravitationTolerance = 1e-14;

struct Totals {
  Vec2 momentum = Vec2::Zero();   // kg·m/s
  double angular_momentum = 0.0;  // kg·m²/s, about the origin
  double energy = 0.0;            // J, kinetic, with rotation (DD:kEnergy)
};

Totals totals(const gp::Scene& scene, const std::vector<gp::BodyState>& states) {
  const auto built = gp::build_space(scene);
  const gp::Space& space = *built;
  Totals t;
  for (gp::BodyId id = 0; id < space.body_count(); ++id) {
    if (space.type(id) != gp::BodyType::Dynamic) continue;
    const gp::BodyState& s = states[id];
    const double m = space.mass(id);
    const double I = std::isinf(space.moment(id)) ? 0.0 : space.moment(id);
    t.momentum += m * s.velocity;
    t.angular_momentum += m * gp::cross(s.position, s.velocity) + I * s.angular_velocity;
    t.energy += gp::dd::kinetic_energy(m, s.velocity, I, s.angular_velocity);
  }
  return t;
}

// A scene with the instants to report, for the scenes that several tests run.
struct Scenario {
  gp::Scene scene;
  std::vector<double> times;
};

// Point masses 3 kg and 1 kg, 2 m apart, G = 1, circling their barycentre at the origin:
// ω² = G (m₁ + m₂) / r³.
constexpr double kOrbitG = 1.0, kOrbitM1 = 3.0, kOrbitM2 = 1.0, kOrbitR = 2.0;
const double kOrbitOmega = std::sqrt(kOrbitG * (kOrbitM1 + kOrbitM2) / std::pow(kOrbitR, 3));

Scenario orbit() {
  gp::Settings settings;
  settings.G = kOrbitG;
  const double r1 = kOrbitR * kOrbitM2 / (kOrbitM1 + kOrbitM2), r2 = kOrbitR - r1;
  gp::BodyDef star;
  star.name = "star";
  star.mass = kOrbitM1;
  star.position = {-r1, 0.0};
  star.velocity = {0.0, -kOrbitOmega * r1};
  gp::BodyDef planet;
  planet.name = "planet";
  planet.mass = kOrbitM2;
  planet.position = {r2, 0.0};
  planet.velocity = {0.0, kOrbitOmega * r2};
  const double period = kTwoPi / kOrbitOmega;
  return {scene_of(settings, {star, planet}), {period / 4, period}};
}

// Discs of 2 kg and 1 kg, radius 0.5, 3 m apart, closing at 2.5 m/s: they touch at t = 1.2 s.
Scenario head_on() {
  return {scene_of({}, {disc("a", {-2.0, 0.0}, {1.5, 0.0}, 0.5, 2.0, 1.0),
                        disc("b", {2.0, 0.0}, {-1.0, 0.0}, 0.5, 1.0, 1.0)}),
          {1.0, 2.0}};
}

// Equal discs of radius 0.5; a at 2 m/s passes b, at rest, with an offset of 0.4 m.
Scenario oblique() {
  return {scene_of({}, {disc("a", {-3.0, 0.4}, {2.0, 0.0}, 0.5, 1.0, 1.0),
                        disc("b", {0.0, 0.0}, {0.0, 0.0}, 0.5, 1.0, 1.0)}),
          {2.0}};
}

// A 0.5 kg disc of radius 0.25 at 4 m/s hits the left face of a free 2 m × 1 m box (2 kg,
// I = m (w² + h²) / 12 = 5/6 kg·m²) at rest, 0.3 m above its centre, at t = 0.4375 s.
Scenario off_centre() {
  gp::BodyDef box;
  box.name = "box";
  box.shapes.push_back({gp::Shape::box(2.0, 1.0), 1.0, 0.0, 1.0});
  return {scene_of({}, {disc("ball", {-3.0, 0.3}, {4.0, 0.0}, 0.25, 0.5, 1.0), box}), {1.0}};
}

// A ball of radius 0.5 and C_R = 0.8 dropped from 10 m (its lowest point) onto a static segment.
constexpr double kG = 9.81, kDrop = 10.0, kBallRadius = 0.5, kBounce = 0.8;
const double kFirstImpact = std::sqrt(2 * kDrop / kG);
const double kImpactSpeed = kG * kFirstImpact;

// t_k of bounce k = 1, 2, …: each flight after bounce k lasts 2 C_R^k v₁ / g.
double bounce_time(int k) {
  double t = kFirstImpact;
  for (int i = 1; i < k; ++i) t += 2 * std::pow(kBounce, i) * kImpactSpeed / kG;
  return t;
}

// Apex after bounce k: C_R^k v₁ / g after t_k.
double apex_time(int k) {
  return bounce_time(k) + std::pow(kBounce, k) * kImpactSpeed / kG;
}

Scenario bouncing_ball() {
  return {
      scene_of(with_gravity(kG), {ground(kBounce), disc("ball", {0.0, kDrop + kBallRadius},
                                                        Vec2::Zero(), kBallRadius, 1.0, kBounce)}),
      {apex_time(1), apex_time(2), apex_time(3)}};
}

// The event times and the final state of every body, of which each entry must agree between the
// two methods within 1e-9 of its own size (or of `scale`).
void check_agreement(const Scenario& scenario, double scale, double tolerance = 1e-12) {
  const OracleResult cvode =
      run_oracle(scenario.scene, scenario.times, tight(OracleMethod::CvodeAdams, tolerance));
  const OracleResult arkode =
      run_oracle(scenario.scene, scenario.times, tight(OracleMethod::ArkodeErk, tolerance));
  REQUIRE(cvode.events.size() == arkode.events.size());
  for (std::size_t e = 0; e < cvode.events.size(); ++e) {
    check_near(arkode.events[e].time, cvode.events[e].time, scale);
    check_near(arkode.events[e].impulse, cvode.events[e].impulse, scale);
  }
  for (std::size_t k = 0; k < cvode.times.size(); ++k) {
    for (std::size_t j = 0; j < cvode.states[k].size(); ++j) {
      const gp::BodyState& c = cvode.states[k][j];
      const gp::BodyState& a = arkode.states[k][j];
      check_near(a.position.x(), c.position.x(), scale);
      check_near(a.position.y(), c.position.y(), scale);
      // Orientations in [0, 2π) differ by about 2π where one is a round-off below zero.
      check_near(std::remainder(a.angle - c.angle, kTwoPi), 0.0, scale);
      check_near(a.velocity.x(), c.velocity.x(), scale);
      check_near(a.velocity.y(), c.velocity.y(), scale);
      check_near(a.angular_velocity, c.angular_velocity, scale);
    }
  }
}

TEST_CASE("Oracle: a projectile follows p0 + v0 t + g t^2 / 2",
          "[via:IM:transMot][via:DD:linDisp][via:DD:linVel][FR:Calculate-Translation-Over-Time]") {
  const auto method =
      GENERATE(OracleMethod::CvodeAdams, OracleMethod::CvodeBdf, OracleMethod::ArkodeErk);
  const gp::Scene scene =
      scene_of(with_gravity(kG), {disc("ball", {1.0, 2.0}, {3.0, 4.0}, 0.5, 1.0, 0.0)});
  const std::vector<double> times{0.0, 0.5, 1.25};
  const OracleResult r = run_oracle(scene, times, tight(method));
  REQUIRE(r.states.size() == times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double t = times[k];
    const gp::BodyState& s = r.states[k][0];
    check_near(s.position.x(), 1.0 + 3.0 * t);
    check_near(s.position.y(), 2.0 + 4.0 * t - 0.5 * kG * t * t);
    check_near(s.velocity.x(), 3.0);
    check_near(s.velocity.y(), 4.0 - kG * t);
  }
}

TEST_CASE(
    "Oracle: a constant torque turns a body by w0 t + alpha t^2 / 2, modulo 2 pi",
    "[via:IM:rotMot][via:TM:NewtonSecLawRotMot][via:DD:angDisp][FR:Calculate-Rotation-Over-Time]") {
  const auto method =
      GENERATE(OracleMethod::CvodeAdams, OracleMethod::CvodeBdf, OracleMethod::ArkodeErk);
  gp::BodyDef wheel;
  wheel.name = "wheel";
  wheel.mass = 1.0;
  wheel.moment = 0.5;
  wheel.torque = 1.5;  // α = τ / I = 3 rad/s²
  wheel.angular_velocity = 0.25;
  const double alpha = 3.0, omega0 = 0.25;
  const std::vector<double> times{1.0, 2.0, 3.0};  // θ = 1.75, 6.5, 14.25 rad
  const OracleResult r = run_oracle(scene_of({}, {wheel}), times, tight(method));
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double t = times[k];
    const double theta = omega0 * t + 0.5 * alpha * t * t;
    const gp::BodyState& s = r.states[k][0];
    CHECK(s.angle >= 0.0);
    CHECK(s.angle < kTwoPi);
    check_near(s.angle, std::fmod(theta, kTwoPi));
    check_near(s.angular_velocity, omega0 + alpha * t);
    check_near(s.position.norm(), 0.0);
  }
}

TEST_CASE("Oracle: a two-body circular orbit closes after one period, keeping E and L",
          "[via:TM:UniversalGravLaw][via:GD:accelGravity][via:IM:transMot][via:DD:kEnergy]") {
  const auto method =
      GENERATE(OracleMethod::CvodeAdams, OracleMethod::CvodeBdf, OracleMethod::ArkodeErk);
  const Scenario s = orbit();
  const OracleResult r = run_oracle(s.scene, s.times, tight(method, kGravitationTolerance));
  const double r1 = kOrbitR * kOrbitM2 / (kOrbitM1 + kOrbitM2), r2 = kOrbitR - r1;
  // A quarter period: a quarter turn counter-clockwise.
  check_near(r.states[0][0].position.y(), -r1, kOrbitR);
  check_near(r.states[0][1].position.y(), r2, kOrbitR);
  check_near(r.states[0][0].position.x(), 0.0, kOrbitR);
  // One period: back at the start.
  const auto& end = r.states[1];
  check_near(end[0].position.x(), -r1, kOrbitR);
  check_near(end[0].position.y(), 0.0, kOrbitR);
  check_near(end[1].position.x(), r2, kOrbitR);
  check_near(end[1].position.y(), 0.0, kOrbitR);
  check_near(end[1].velocity.y(), kOrbitOmega * r2, kOrbitOmega * kOrbitR);
  // E = −G m₁ m₂ / (2 r) and L = μ r² ω with μ = m₁ m₂ / (m₁ + m₂).
  const Totals after = totals(s.scene, end);
  const double separation = (end[1].position - end[0].position).norm();
  check_near(after.energy - kOrbitG * kOrbitM1 * kOrbitM2 / separation,
             -kOrbitG * kOrbitM1 * kOrbitM2 / (2 * kOrbitR));
  check_near(after.angular_momentum,
             kOrbitM1 * kOrbitM2 / (kOrbitM1 + kOrbitM2) * kOrbitR * kOrbitR * kOrbitOmega);
  check_near(after.momentum.norm(), 0.0);
  CHECK(r.events.empty());
}

TEST_CASE("Oracle: discs falling together by gravitation touch at the radial Kepler time",
          "[via:TM:UniversalGravLaw][via:GD:accelGravity][via:IM:col2D]") {
  const auto method =
      GENERATE(OracleMethod::CvodeAdams, OracleMethod::CvodeBdf, OracleMethod::ArkodeErk);
  // Two 1 kg discs of radius 0.5 at rest 4 m apart, G = 1: the separation r falls from r₀ = 4
  // to 1 as in a radial Kepler orbit with μ = G (m₁ + m₂) = 2, in
  //   t_c = √(r₀³ / 2μ) (√(x (1 − x)) + arccos √x),  x = 1 / r₀,
  // and, elastic, they climb back to rest at r₀ at 2 t_c and touch again at 3 t_c.
  gp::Settings settings;
  settings.G = 1.0;
  const gp::Scene scene = scene_of(settings, {disc("a", {-2.0, 0.0}, Vec2::Zero(), 0.5, 1.0, 1.0),
                                              disc("b", {2.0, 0.0}, Vec2::Zero(), 0.5, 1.0, 1.0)});
  const double r0 = 4.0, mu = 2.0, x = 1.0 / r0;
  const double tc =
      std::sqrt(r0 * r0 * r0 / (2 * mu)) * (std::sqrt(x * (1 - x)) + std::acos(std::sqrt(x)));
  const OracleResult r = run_oracle(scene, std::vector<double>{2 * tc, 3.5 * tc},
                                    tight(method, kGravitationTolerance));
  REQUIRE(r.events.size() == 2);
  check_near(r.events[0].time, tc);
  check_near(r.events[1].time, 3 * tc);
  check_near(r.states[0][1].position.x(), 2.0);
  check_near(r.states[0][1].velocity.x(), 0.0);
}

TEST_CASE("Oracle: a head-on elastic collision of discs at its exact time",
          "[via:IM:col2D][via:GD:impulse][FR:Determine-Collisions]") {
  const auto method =
      GENERATE(OracleMethod::CvodeAdams, OracleMethod::CvodeBdf, OracleMethod::ArkodeErk);
  const Scenario s = head_on();
  const OracleResult r = run_oracle(s.scene, s.times, tight(method));
  REQUIRE(r.events.size() == 1);
  const double tc = 1.2;
  check_near(r.events[0].time, tc);
  CHECK(r.events[0].body_a == 0);
  CHECK(r.events[0].body_b == 1);
  check_near(r.events[0].normal.x(), -1.0);  // from b towards a
  check_near(r.events[0].normal.y(), 0.0);
  // 1D elastic: v_a' = ((m_a − m_b) v_a + 2 m_b v_b) / (m_a + m_b), and b alike.
  const double ma = 2.0, mb = 1.0, va = 1.5, vb = -1.0;
  const double va_after = ((ma - mb) * va + 2 * mb * vb) / (ma + mb);
  const double vb_after = ((mb - ma) * vb + 2 * ma * va) / (ma + mb);
  check_near(r.events[0].impulse, ma * (va - va_after));
  const auto& end = r.states[1];
  check_near(end[0].velocity.x(), va_after);
  check_near(end[1].velocity.x(), vb_after);
  check_near(end[0].position.x(), -2.0 + va * tc + va_after * (2.0 - tc));
  check_near(end[1].position.x(), 2.0 + vb * tc + vb_after * (2.0 - tc));
  // Before the impact, free flight.
  check_near(r.states[0][0].position.x(), -2.0 + va * 1.0);
}

TEST_CASE("Oracle: an oblique elastic collision of equal discs",
          "[via:IM:col2D][via:GD:impulse][via:DD:reVeInColl]") {
  const auto method =
      GENERATE(OracleMethod::CvodeAdams, OracleMethod::CvodeBdf, OracleMethod::ArkodeErk);
  const Scenario s = oblique();
  const OracleResult r = run_oracle(s.scene, s.times, tight(method));
  REQUIRE(r.events.size() == 1);
  // |p_a(t) − p_b| = 1 when (−3 + 2t)² + 0.4² = 1.
  const double root = std::sqrt(1.0 - 0.16);
  const double tc = (3.0 - root) / 2.0;
  check_near(r.events[0].time, tc);
  const Vec2 n(-root, 0.4);  // from b towards a at contact, unit since the distance is 1
  check_near(r.events[0].normal.x(), n.x());
  check_near(r.events[0].normal.y(), n.y());
  // Equal masses, b at rest, elastic: b takes a's velocity along n, a keeps the rest.
  const Vec2 va(2.0, 0.0);
  const Vec2 va_after = va - va.dot(n) * n, vb_after = va.dot(n) * n;
  const auto& end = r.states[0];
  check_near(end[0].velocity.x(), va_after.x());
  check_near(end[0].velocity.y(), va_after.y());
  check_near(end[1].velocity.x(), vb_after.x());
  check_near(end[1].velocity.y(), vb_after.y());
  check_near(end[1].position.x(), vb_after.x() * (2.0 - tc));
  check_near(end[1].position.y(), vb_after.y() * (2.0 - tc));
}

TEST_CASE("Oracle: an off-centre impact on a free box conserves momentum, L and E",
          "[via:IM:col2D][via:GD:impulse][via:DD:torque][via:DD:kEnergy]") {
  const auto method =
      GENERATE(OracleMethod::CvodeAdams, OracleMethod::CvodeBdf, OracleMethod::ArkodeErk);
  const Scenario s = off_centre();
  const OracleResult r = run_oracle(s.scene, std::vector<double>{0.0, 1.0}, tight(method));
  REQUIRE(r.events.size() == 1);
  check_near(r.events[0].time, (3.0 - 1.0 - 0.25) / 4.0);
  check_near(r.events[0].point.x(), -1.0);
  check_near(r.events[0].point.y(), 0.3);
  // GD:impulse: j = −(1 + C_R) v·n / (1/m_a + 1/m_b + (r_b × n)² / I_b), n = (−1, 0),
  // r_b = (−1, 0.3): r_b × n = 0.3.
  const double mb = 2.0, Ib = mb * (4.0 + 1.0) / 12.0;
  REQUIRE(gp::build_space(s.scene)->moment(1) == Approx(Ib));
  const double j = 2.0 * 4.0 / (1.0 / 0.5 + 1.0 / mb + 0.3 * 0.3 / Ib);
  check_near(r.events[0].impulse, j);
  const Totals before = totals(s.scene, r.states[0]);
  const Totals after = totals(s.scene, r.states[1]);
  check_near(after.momentum.x(), before.momentum.x());
  check_near(after.momentum.y(), before.momentum.y(), before.momentum.norm());
  check_near(after.angular_momentum, before.angular_momentum);
  check_near(after.energy, before.energy);
  check_near(r.states[1][1].angular_velocity, -0.3 * j / Ib);  // hit above the centre: clockwise
}

TEST_CASE("Oracle: a kinematic paddle moves in closed form and bats a disc at twice its speed",
          "[via:IM:col2D][FR:Determine-Collision-Response-Over-Time]") {
  const auto method =
      GENERATE(OracleMethod::CvodeAdams, OracleMethod::CvodeBdf, OracleMethod::ArkodeErk);
  gp::BodyDef paddle;
  paddle.name = "paddle";
  paddle.type = gp::BodyType::Kinematic;
  paddle.position = {-2.0, 0.0};
  paddle.velocity = {1.0, 0.0};
  paddle.angular_velocity = 0.5;  // a spinning disc: frictionless, so the spin does not matter
  paddle.shapes.push_back({gp::Shape::circle(0.5), 1.0});
  const gp::Scene scene =
      scene_of({}, {paddle, disc("ball", {0.0, 0.0}, Vec2::Zero(), 0.5, 1.0, 1.0)});
  const OracleResult r = run_oracle(scene, std::vector<double>{2.0}, tight(method));
  // The 1 m gap closes at 1 m/s; against an infinite mass the ball leaves at (1 + C_R) · 1 m/s.
  REQUIRE(r.events.size() == 1);
  check_near(r.events[0].time, 1.0);
  const gp::BodyState& p = r.states[0][0];
  const gp::BodyState& ball = r.states[0][1];
  check_near(p.position.x(), 0.0, 2.0);
  check_near(p.velocity.x(), 1.0);
  check_near(p.angle, 1.0);
  check_near(ball.velocity.x(), 2.0);
  check_near(ball.position.x(), 2.0 * (2.0 - 1.0));
}

TEST_CASE("Oracle: a bouncing ball's impact times and apex heights h_k = C_R^(2k) h0",
          "[via:IM:col2D][via:DD:coeffRestitution][via:GD:impulse][via:IM:transMot]") {
  const auto method =
      GENERATE(OracleMethod::CvodeAdams, OracleMethod::CvodeBdf, OracleMethod::ArkodeErk);
  const Scenario s = bouncing_ball();
  const OracleResult r = run_oracle(s.scene, s.times, tight(method));
  REQUIRE(r.events.size() == 3);
  for (int k = 1; k <= 3; ++k) {
    const auto& e = r.events[k - 1];
    check_near(e.time, bounce_time(k));
    CHECK(e.body_a == 0);  // the ground, added first
    check_near(e.normal.y(), -1.0);
    // j = m (1 + C_R) C_R^(k−1) v₁ for the ball of 1 kg.
    check_near(e.impulse, (1 + kBounce) * std::pow(kBounce, k - 1) * kImpactSpeed);
    const gp::BodyState& apex = r.states[k - 1][1];
    check_near(apex.position.y() - kBallRadius, std::pow(kBounce, 2 * k) * kDrop);
    check_near(apex.velocity.y(), 0.0, kImpactSpeed);
  }
}

TEST_CASE("Oracle: CVODE and ARKODE agree to 1e-9 on every closed-form scene",
          "[via:IM:transMot][via:IM:col2D][LC:Variable-ODE-Solver]") {
  SECTION("orbit") {
    check_agreement(orbit(), kOrbitR, kGravitationTolerance);
  }
  SECTION("head-on") {
    check_agreement(head_on(), 1.0);
  }
  SECTION("oblique") {
    check_agreement(oblique(), 1.0);
  }
  SECTION("off-centre") {
    check_agreement(off_centre(), 1.0);
  }
  SECTION("bouncing ball") {
    check_agreement(bouncing_ball(), kDrop);
  }
}

TEST_CASE("Oracle: a ball resting on the ground at the start stays there",
          "[via:IM:col2D][FR:Determine-Collisions]") {
  const gp::Scene scene = scene_of(
      with_gravity(kG),
      {ground(0.5), disc("ball", {0.0, kBallRadius}, Vec2::Zero(), kBallRadius, 1.0, 0.5)});
  const OracleResult r = run_oracle(scene, std::vector<double>{1.0});
  check_near(r.states[0][1].position.y(), kBallRadius);
  check_near(r.states[0][1].velocity.y(), 0.0);
  CHECK(r.events.empty());
  CHECK(r.largest_drift <= 1e-12);
}

TEST_CASE("Oracle: bodies overlapping at the start are outside its domain",
          "[FR:Determine-Collisions]") {
  const gp::Scene scene = scene_of({}, {disc("a", {0.0, 0.0}, Vec2::Zero(), 0.5, 1.0, 1.0),
                                        disc("b", {0.5, 0.0}, Vec2::Zero(), 0.5, 1.0, 1.0)});
  REQUIRE_THROWS_WITH(run_oracle(scene, std::vector<double>{1.0}), Catch::Contains("overlap"));
}

TEST_CASE("Oracle: a perfectly inelastic impact on the ground ends in resting contact",
          "[via:IM:col2D][via:DD:coeffRestitution]") {
  const gp::Scene scene =
      scene_of(with_gravity(kG),
               {ground(0.0), disc("ball", {0.0, 1.5}, Vec2::Zero(), kBallRadius, 1.0, 0.0)});
  const double landing = std::sqrt(2.0 / kG);
  const OracleResult r = run_oracle(scene, std::vector<double>{0.5 * landing, 10.0});
  REQUIRE(r.events.size() == 1);
  check_near(r.events[0].time, landing);
  check_near(r.events[0].impulse, kG * landing);  // m v for the ball of 1 kg
  check_near(r.states[0][1].position.y(), 1.5 - 0.5 * kG * 0.25 * landing * landing);
  check_near(r.states[1][1].position.y(), kBallRadius);
  check_near(r.states[1][1].velocity.y(), 0.0);
}

TEST_CASE(
    "Oracle: a Zeno sequence of bounces ends at rest once arrivals are slower than the "
    "rest speed",
    "[via:IM:col2D][via:DD:coeffRestitution]") {
  // C_R = 0.5 from 1 m: the bounces would go on for ever, ending at t = 3 t₁ = 1.36 s.
  const gp::Scene scene =
      scene_of(with_gravity(kG),
               {ground(0.5), disc("ball", {0.0, 1.5}, Vec2::Zero(), kBallRadius, 1.0, 0.5)});
  const double t1 = std::sqrt(2.0 / kG), v1 = kG * t1;
  SECTION("at rest after finitely many bounces") {
    OracleOptions options;
    const OracleResult r = run_oracle(scene, std::vector<double>{10.0}, options);
    // Impact k arrives at C_R^k v₁ and rebounds at C_R^(k+1) v₁; the first rebound slower than
    // the rest speed does not leave the ground.
    const auto impacts =
        static_cast<std::size_t>(std::ceil(std::log(options.rest_speed / v1) / std::log(0.5)));
    CHECK(r.events.size() == impacts);
    for (std::size_t k = 0; k < r.events.size(); ++k) {
      // t_k = t₁ (1 + 2 Σ_{0<i≤k} C_R^i) = t₁ (3 − 2^(1−k)). Where the ball is found touching
      // is exact to about 1e-11 m; the time that error makes grows as the arrivals slow down.
      const double arrival = v1 * std::pow(0.5, static_cast<double>(k));
      INFO("impact " << k << ", arriving at " << arrival << " m/s");
      const double expected = t1 * (3.0 - std::pow(2.0, 1.0 - static_cast<double>(k)));
      CHECK(std::abs(r.events[k].time - expected) <=
            std::max(gp::test::kOracleRelative * expected, 1e-11 / arrival));
    }
    check_near(r.states[0][1].position.y(), kBallRadius);
    check_near(r.states[0][1].velocity.y(), 0.0);
  }
  SECTION("too many impacts") {
    OracleOptions options;
    options.max_events = 3;
    REQUIRE_THROWS_WITH(run_oracle(scene, std::vector<double>{100.0}, options),
                        Catch::Contains("more than 3 events"));
  }
  SECTION("too many impacts in a short time") {
    OracleOptions options;
    options.zeno_events = 4;
    options.zeno_window = 1.0;
    REQUIRE_THROWS_WITH(run_oracle(scene, std::vector<double>{100.0}, options),
                        Catch::Contains("Zeno"));
  }
}

TEST_CASE("Oracle: a solver failure is a domain error naming the method", "[via:IM:transMot]") {
  const auto method =
      GENERATE(OracleMethod::CvodeAdams, OracleMethod::CvodeBdf, OracleMethod::ArkodeErk);
  const Scenario s = orbit();
  OracleOptions options = tight(method);
  options.max_steps = 5;
  REQUIRE_THROWS_WITH(run_oracle(s.scene, s.times, options),
                      Catch::Contains(std::string(gp::verification::oracle_method_name(method))));
}

TEST_CASE("Oracle: a spinning disc lands on a frictional floor and sticks or slides by Coulomb",
          "[via:IM:col2D][via:DD:coeffRestitution][FR:Input-Surface-Properties]") {
  // A uniform disc (m = 1 kg, r = 0.5 m, I = m r²/2) dropped 1 m onto a floor, C_R = 0.5,
  // μ = 0.5, with horizontal speed vₓ and spin ω. The normal impulse is j = m (1 + C_R) v₁; the
  // floor's point slips at s = vₓ + ω r, and the tangential impulse that stops it is m s / 3
  // (1/m + r²/I = 3/m). Coulomb: that impulse if it is within μ j, else μ j against the slip.
  constexpr double kMu = 0.5, kRestitution = 0.5, kMass = 1.0, kMoment = 0.125;
  struct Case {
    double vx, omega;
    bool sticks;
  };
  const Case c = GENERATE(Case{1.0, 0.0, true}, Case{0.0, 40.0, false}, Case{2.0, -30.0, false},
                          Case{0.0, 0.0, true});
  INFO("vx = " << c.vx << " m/s, omega = " << c.omega << " rad/s");
  gp::BodyDef floor = ground(kRestitution);
  floor.shapes[0].friction = kMu;
  gp::BodyDef ball = disc("ball", {0.0, 1.5}, {c.vx, 0.0}, kBallRadius, kMass, kRestitution);
  ball.angular_velocity = c.omega;
  ball.shapes[0].friction = kMu;
  const double landing = std::sqrt(2.0 / kG), v1 = kG * landing, later = landing + 0.2;
  const gp::Scene scene = scene_of(with_gravity(kG), {floor, ball});
  const OracleResult r = run_oracle(scene, std::vector<double>{later});
  REQUIRE(r.events.size() == 1);
  check_near(r.events[0].time, landing);
  const double j = kMass * (1.0 + kRestitution) * v1;
  check_near(r.events[0].impulse, j);
  const double slip = c.vx + c.omega * kBallRadius;
  const double stop = kMass * slip / 3.0;
  CHECK((std::abs(stop) <= kMu * j) == c.sticks);
  const double pt = c.sticks ? stop : std::copysign(kMu * j, slip);  // along −x on the disc
  const double vx = c.vx - pt / kMass, omega = c.omega - kBallRadius * pt / kMoment;
  const gp::BodyState& s = r.states[0][1];
  check_near(s.velocity.x(), vx);
  check_near(s.angular_velocity, omega, 10.0);
  check_near(s.velocity.y(), kRestitution * v1 - kG * 0.2);
  check_near(s.position.x(), c.vx * landing + vx * 0.2);
  if (c.sticks) check_near(vx + omega * kBallRadius, 0.0);  // it leaves the floor rolling
  // The impact loses energy: the oracle's state after it has less than the drop began with.
  const double start =
      0.5 * kMoment * c.omega * c.omega + 0.5 * kMass * c.vx * c.vx + kMass * kG * 1.5;
  const double now = 0.5 * kMoment * s.angular_velocity * s.angular_velocity +
                     0.5 * kMass * s.velocity.squaredNorm() + kMass * kG * s.position.y();
  CHECK(now < start);
}

TEST_CASE("Oracle: without dynamic bodies, kinematic ones move in closed form",
          "[via:DD:linDisp][via:DD:angDisp]") {
  gp::BodyDef k;
  k.name = "conveyor";
  k.type = gp::BodyType::Kinematic;
  k.velocity = {2.0, -1.0};
  k.angular_velocity = -1.0;
  const OracleResult r = run_oracle(scene_of({}, {k}), std::vector<double>{0.0, 3.0});
  check_near(r.states[1][0].position.x(), 6.0);
  check_near(r.states[1][0].position.y(), -3.0);
  check_near(r.states[1][0].angle, kTwoPi - 3.0);
  CHECK(r.steps == 0);
}

TEST_CASE("Oracle: method names and bad options", "[LC:Variable-ODE-Solver]") {
  using gp::verification::oracle_method_from_name;
  using gp::verification::oracle_method_name;
  for (auto m : {OracleMethod::CvodeAdams, OracleMethod::CvodeBdf, OracleMethod::ArkodeErk}) {
    CHECK(oracle_method_from_name(oracle_method_name(m)) == m);
  }
  CHECK_FALSE(oracle_method_from_name("euler"));
  const gp::Scene scene = scene_of({}, {disc("ball", Vec2::Zero(), Vec2::Zero(), 0.5, 1.0, 0.0)});
  const std::vector<double> times{1.0};
  OracleOptions options;
  options.rtol = 0.0;
  CHECK_THROWS_AS(run_oracle(scene, times, options), std::invalid_argument);
  options = {};
  options.atol = -1.0;
  CHECK_THROWS_AS(run_oracle(scene, times, options), std::invalid_argument);
  options = {};
  options.contact_tolerance = 0.0;
  CHECK_THROWS_AS(run_oracle(scene, times, options), std::invalid_argument);
  options = {};
  options.zeno_events = 1;
  CHECK_THROWS_AS(run_oracle(scene, times, options), std::invalid_argument);
  CHECK_THROWS_AS(run_oracle(scene, std::vector<double>{2.0, 1.0}), std::invalid_argument);
}

TEST_CASE("Oracle: the trajectory CSV is simulate's format, the impact log one row per impact",
          "[via:IM:col2D][FR:Determine-Collision-Response-Over-Time]") {
  const Scenario s = head_on();
  const OracleResult r = run_oracle(s.scene, std::vector<double>{0.0, 2.0});
  std::ostringstream trajectory, impacts;
  gp::verification::write_trajectory(trajectory, s.scene, r);
  gp::verification::write_impacts(impacts, s.scene, r);
  std::istringstream rows(trajectory.str());
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(rows, line)) lines.push_back(line);
  REQUIRE(lines.size() == 5);  // the header, 2 instants × 2 bodies
  CHECK(lines[0] == "t,body,x,y,angle,vx,vy,omega");
  CHECK(lines[1] == "0,a,-2,0,0,1.5,0,0");
  CHECK(lines[4].rfind("2,b,", 0) == 0);
  std::istringstream log(impacts.str());
  REQUIRE(std::getline(log, line));
  CHECK(line == "t,body_a,body_b,nx,ny,impulse");
  REQUIRE(std::getline(log, line));
  // t_c = 1.2 s to the last bits the solver found; then the names, the normal and j.
  CHECK(std::stod(line.substr(0, line.find(','))) == Approx(1.2).epsilon(1e-12));
  CHECK(line.substr(line.find(',')) == ",a,b,-1,0,3.3333333333333335");
  CHECK_FALSE(std::getline(log, line));
}

}  // namespace test_oracle
}  // namespace
