// The oracle through contact, against closed forms on the shipped contact scenes: a block
// sliding down a ramp, a disc rolling without slipping, a box held by static friction, a box
// dropped flat that comes to rest (and one landing while it slides), a stack at rest, a box tipping
// over the edge of a step and one sliding off the end of a line; each within 1e-9 with every
// method, its constraints held to 1e-12 m, and CVODE and ARKODE agreeing to 1e-9. The first four
// are also exact under the time-stepping reference.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "check_near.hpp"
#include "oracle_scenes.hpp"
#include "scene/scene.hpp"
#include "verification/oracle/oracle.hpp"

using gp::Vec2;
using gp::verification::OracleMethod;
using gp::verification::OracleResult;
using gp::verification::run_oracle;

using gp::test::check_near;
using gp::test::with;

namespace {
namespace test_oracle_contact_scenes {

constexpr double kDrift = 1e-12;  // m: how far an active contact may drift off its constraint
constexpr double kG = 9.81;

gp::Scene shipped(const std::string& name) {
  return gp::load_scene(std::string(GP_SOURCE_DIR) + "/scenes/" + name + ".json");
}

std::vector<double> instants(const gp::Scene& scene) {
  std::vector<double> times;
  const auto n = static_cast<int>(std::lround(scene.duration / scene.output_dt));
  for (int k = 0; k <= n; ++k) times.push_back(k * scene.output_dt);
  return times;
}

const auto kMethods = {OracleMethod::CvodeAdams, OracleMethod::CvodeBdf, OracleMethod::ArkodeErk};
// Where every contact holds from the start and the accelerations are uniform, time-stepping is
// exact too: velocities change by h a a step, and positions by h (v⁻ + v⁺) / 2.
const auto kMethodsAndStepping = {OracleMethod::CvodeAdams, OracleMethod::CvodeBdf,
                                  OracleMethod::ArkodeErk, OracleMethod::TimeStepping};

// Body `body` moving from rest along unit `direction` with acceleration `a` (m/s²).
void check_uniform_acceleration(const OracleResult& r, std::size_t body, const Vec2& start,
                                const Vec2& direction, double a) {
  for (std::size_t k = 0; k < r.times.size(); ++k) {
    const double t = r.times[k];
    INFO("t = " << t);
    const gp::BodyState& s = r.states[k][body];
    const Vec2 p = start + 0.5 * a * t * t * direction;
    check_near(s.position.x(), p.x());
    check_near(s.position.y(), p.y());
    check_near(s.velocity.x(), a * t * direction.x());
    check_near(s.velocity.y(), a * t * direction.y());
  }
}

TEST_CASE("oracle: a block slides down a 30-degree ramp at g (sin θ − μ cos θ)",
          "[oracle][contact]") {
  const gp::Scene scene = shipped("ramp_slide");
  const double theta = std::numbers::pi / 6, mu = 0.2;
  const Vec2 down(-std::cos(theta), -std::sin(theta));
  for (OracleMethod method : kMethodsAndStepping) {
    const OracleResult r = run_oracle(scene, instants(scene), with(method));
    check_uniform_acceleration(r, 1, scene.bodies[1].position, down,
                               kG * (std::sin(theta) - mu * std::cos(theta)));
    CHECK(r.largest_drift <= kDrift);
    CHECK(r.events.empty());
  }
}

TEST_CASE("oracle: a disc rolls down a 30-degree ramp at 2/3 g sin θ with ω = v / r",
          "[oracle][contact]") {
  const gp::Scene scene = shipped("disc_roll");
  const double theta = std::numbers::pi / 6, radius = 0.5;
  const Vec2 down(-std::cos(theta), -std::sin(theta));
  for (OracleMethod method : kMethodsAndStepping) {
    const OracleResult r = run_oracle(scene, instants(scene), with(method));
    const double a = 2.0 / 3.0 * kG * std::sin(theta);
    check_uniform_acceleration(r, 1, scene.bodies[1].position, down, a);
    for (std::size_t k = 0; k < r.times.size(); ++k) {
      check_near(r.states[k][1].angular_velocity, a * r.times[k] / radius);
    }
    CHECK(r.largest_drift <= kDrift);
  }
}

TEST_CASE("oracle: static friction holds a box on a 20-degree slope", "[oracle][contact]") {
  const gp::Scene scene = shipped("static_friction");
  for (OracleMethod method : kMethodsAndStepping) {
    const OracleResult r = run_oracle(scene, instants(scene), with(method));
    check_uniform_acceleration(r, 1, scene.bodies[1].position, Vec2(1, 0), 0.0);
    for (const auto& states : r.states) check_near(states[1].angular_velocity, 0.0);
    CHECK(r.largest_drift <= kDrift);
  }
}

TEST_CASE("oracle: a box dropped flat with C_R = 0 lands at sqrt(2h/g) and rests",
          "[oracle][contact]") {
  const gp::Scene scene = shipped("box_drop");
  const double landing = std::sqrt(2.0 / kG);
  for (OracleMethod method : kMethods) {
    const OracleResult r = run_oracle(scene, instants(scene), with(method));
    REQUIRE_FALSE(r.events.empty());
    for (const auto& e : r.events) check_near(e.time, landing);
    for (std::size_t k = 0; k < r.times.size(); ++k) {
      const double t = r.times[k];
      INFO("t = " << t);
      const gp::BodyState& s = r.states[k][1];
      check_near(s.position.x(), 0.0);
      check_near(s.position.y(), t < landing ? 1.5 - 0.5 * kG * t * t : 0.5);
      check_near(s.velocity.y(), t < landing ? -kG * t : 0.0);
      check_near(s.angular_velocity, 0.0);
    }
    CHECK(r.largest_drift <= kDrift);
  }
}

TEST_CASE("oracle: a box landing flat while sliding loses mu v_y at impact, then slides to rest",
          "[oracle][contact]") {
  // box_drop with μ = 0.1 and vₓ = 1 m/s: both corners land at once (C_R = 0) at v_y = g t_L;
  // the impact's friction impulse is μ m v_y < m vₓ, so it slides on at vₓ − μ v_y, decelerates
  // at μ g and stops. Its normal impulses differ so that it does not turn.
  gp::Scene scene = shipped("box_drop");
  constexpr double kMu = 0.1, kVx = 1.0;
  for (gp::BodyDef& body : scene.bodies) body.shapes[0].friction = kMu;
  scene.bodies[1].velocity = {kVx, 0.0};
  const double landing = std::sqrt(2.0 / kG), after = kVx - kMu * kG * landing;
  const double stop = landing + after / (kMu * kG);
  std::vector<double> times;
  for (int k = 0; k <= 30; ++k) times.push_back(0.05 * k);
  for (OracleMethod method : kMethods) {
    const OracleResult r = run_oracle(scene, times, with(method));
    REQUIRE_FALSE(r.events.empty());
    double impulse = 0.0;
    for (const auto& e : r.events) {
      check_near(e.time, landing);
      impulse += e.impulse;
    }
    check_near(impulse, kG * landing);  // m v_y, the box of 1 kg
    for (std::size_t k = 0; k < r.times.size(); ++k) {
      const double t = r.times[k];
      INFO("t = " << t);
      const double tau = std::min(std::max(t - landing, 0.0), stop - landing);
      const gp::BodyState& s = r.states[k][1];
      check_near(s.position.x(),
                 t < landing ? kVx * t : kVx * landing + after * tau - 0.5 * kMu * kG * tau * tau);
      check_near(s.velocity.x(), t < landing ? kVx : after - kMu * kG * tau);
      check_near(s.position.y(), t < landing ? 1.5 - 0.5 * kG * t * t : 0.5);
      check_near(s.angular_velocity, 0.0);
    }
    CHECK(r.largest_drift <= kDrift);
  }
}

TEST_CASE("oracle: a stack of three boxes stays at rest", "[oracle][contact]") {
  const gp::Scene scene = shipped("stack3");
  for (OracleMethod method : kMethodsAndStepping) {
    const OracleResult r = run_oracle(scene, instants(scene), with(method));
    for (std::size_t body = 1; body < 4; ++body) {
      check_uniform_acceleration(r, body, scene.bodies[body].position, Vec2(1, 0), 0.0);
    }
    CHECK(r.largest_drift <= kDrift);
  }
}

TEST_CASE("oracle: a box tips over the edge of a step, turning about it as a pendulum",
          "[oracle][contact]") {
  const gp::Scene scene = shipped("step_tip");
  // The unit box of 1 kg/m² turns about the step's corner at the origin while friction holds it:
  // I_corner ω² / 2 = m g (y₀ − y), with I_corner = m (1 + 1)/12 + m d².
  const Vec2 start = scene.bodies[1].position;
  const double d2 = start.squaredNorm();
  const double I_corner = 2.0 / 12.0 + d2;
  for (OracleMethod method : kMethods) {
    const OracleResult r = run_oracle(scene, instants(scene), with(method));
    int pivoting = 0;
    for (std::size_t k = 0; k < r.times.size(); ++k) {
      const gp::BodyState& s = r.states[k][1];
      if (std::abs(s.position.squaredNorm() - d2) > 1e-6) break;  // no longer on the corner
      ++pivoting;
      INFO("t = " << r.times[k]);
      check_near(s.position.squaredNorm(), d2);
      check_near(0.5 * I_corner * s.angular_velocity * s.angular_velocity,
                 kG * (start.y() - s.position.y()));
    }
    CHECK(pivoting >= 8);
  }
}

TEST_CASE("oracle: a box sliding off the end of a line tips and then falls freely",
          "[oracle][contact]") {
  // A frictionless unit box slides at 0.5 m/s off the right end (10, 0) of a static line: its
  // centre passes the end at t = 2 s, it tips over the end and leaves it before t = 3 s. From
  // then on nothing holds it: between t = 3 s and 4 s it is a projectile, v_x and ω constant,
  // y(4) = y(3) + v_y(3) − g/2. (A vertex that reached the end of its edge was once left
  // unwatched there, and rode the line beyond the end, holding the box up.)
  gp::BodyDef ground;
  ground.name = "ground";
  ground.type = gp::BodyType::Static;
  ground.shapes.push_back({gp::Shape::segment({-10.0, 0.0}, {10.0, 0.0})});
  gp::BodyDef box;
  box.name = "box";
  box.position = {9.0, 0.5};
  box.velocity = {0.5, 0.0};
  box.shapes.push_back({gp::Shape::box(1.0, 1.0)});
  gp::Scene scene{{}, 0.001, 4.0, 1.0, {ground, box}};
  scene.settings.gravity = {0.0, -kG};
  for (OracleMethod method : kMethods) {
    const OracleResult r = run_oracle(scene, std::vector<double>{3.0, 4.0}, with(method));
    const gp::BodyState& a = r.states[0][1];
    const gp::BodyState& b = r.states[1][1];
    INFO("method " << static_cast<int>(method));
    CHECK(a.position.y() < 0.0);  // below the line: it has tipped off
    check_near(b.position.x(), a.position.x() + a.velocity.x(), 10.0);
    check_near(b.position.y(), a.position.y() + a.velocity.y() - 0.5 * kG, 10.0);
    check_near(b.velocity.x(), a.velocity.x(), 10.0);
    check_near(b.velocity.y(), a.velocity.y() - kG, 10.0);
    check_near(b.angular_velocity, a.angular_velocity, 10.0);
  }
}

TEST_CASE("oracle: CVODE and ARKODE agree to 1e-9 on every contact scene", "[oracle][contact]") {
  for (const char* name : {"ramp_slide", "disc_roll", "static_friction", "box_drop", "stack3",
                           "step_tip", "heavy_stack"}) {
    INFO(name);
    gp::Scene scene = shipped(name);
    // One second holds every scene's events (box_drop lands at 0.45 s, stack3 and heavy_stack
    // stand) and keeps the test short under the sanitizers: ARKODE's steps cost heavy_stack most.
    scene.duration = std::min(scene.duration, 1.0);
    const auto times = instants(scene);
    const OracleResult bdf = run_oracle(scene, times, with(OracleMethod::CvodeBdf));
    const OracleResult erk = run_oracle(scene, times, with(OracleMethod::ArkodeErk));
    double largest = 0.0;
    for (std::size_t k = 0; k < times.size(); ++k) {
      for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
        largest = std::max(largest, (bdf.states[k][b].position - erk.states[k][b].position).norm());
      }
    }
    CHECK(largest <= 1e-9);
  }
}

// Equal discs (r = 0.5 m) in a hexagonal lattice filling a box of three static segments 5 m
// wide: rows of five touching each other and both walls, alternating with rows of four nested
// in them, every disc touching its neighbours. The contact forces are not unique (a row of five
// between two walls can carry any horizontal thrust); the motion is: nothing moves.
gp::Scene jammed_lattice(int rows, double friction) {
  gp::Scene scene{};
  scene.settings.gravity = {0.0, -kG};
  scene.bodies.push_back(gp::test::open_box(2.5, 10.0, friction));
  for (int row = 0; row < rows; ++row) {
    const int count = row % 2 == 0 ? 5 : 4;
    for (int k = 0; k < count; ++k) {
      gp::BodyDef disc;
      disc.name = "disc" + std::to_string(row) + "_" + std::to_string(k);
      disc.position = {k - (count - 1) / 2.0, 0.5 + row * std::sqrt(3.0) / 2.0};
      disc.shapes.push_back({gp::Shape::circle(0.5), 0.0, friction});
      scene.bodies.push_back(disc);
    }
  }
  return scene;
}

TEST_CASE("oracle: a jammed hexagonal lattice of equal discs stays at rest", "[oracle][contact]") {
  const double friction = GENERATE(0.0, 0.5);
  INFO("mu = " << friction);
  const gp::Scene scene = jammed_lattice(4, friction);
  const OracleResult r = run_oracle(scene, std::vector<double>{0.5, 1.0});
  for (const auto& states : r.states) {
    for (std::size_t b = 1; b < scene.bodies.size(); ++b) {
      INFO(scene.bodies[b].name);
      check_near(states[b].position.x(), scene.bodies[b].position.x());
      check_near(states[b].position.y(), scene.bodies[b].position.y());
      check_near(states[b].velocity.norm(), 0.0);
      check_near(states[b].angular_velocity, 0.0);
    }
  }
  CHECK(r.events.empty());
  CHECK(r.largest_drift <= kDrift);
}

TEST_CASE("oracle: a disc dropped into a pocket of a jammed lattice stops dead, the lattice holds",
          "[oracle][contact]") {
  // The lattice's top row (four discs) leaves a pocket at x = 0, √3/2 m above it; a disc dropped
  // 0.5 m into it (C_R = 0) strikes two discs at once, symmetrically, and the rigid lattice
  // takes the whole impulse m v through its redundant contacts to the box: it stops dead.
  const double friction = GENERATE(0.0, 0.5);
  INFO("mu = " << friction);
  gp::Scene scene = jammed_lattice(4, friction);
  const double rest = 0.5 + 4.0 * std::sqrt(3.0) / 2.0, drop = 0.5;
  gp::BodyDef disc;
  disc.name = "dropped";
  disc.mass = 1.0;
  disc.position = {0.0, rest + drop};
  disc.shapes.push_back({gp::Shape::circle(0.5), 0.0, friction});
  scene.bodies.push_back(disc);
  const double landing = std::sqrt(2.0 * drop / kG);
  const OracleResult r = run_oracle(scene, std::vector<double>{0.5 * landing, 1.0});
  REQUIRE_FALSE(r.events.empty());
  double impulse = 0.0;
  for (const auto& e : r.events) {
    check_near(e.time, landing);
    if (e.body_a == scene.bodies.size() - 1 || e.body_b == scene.bodies.size() - 1) {
      impulse += std::abs(e.normal.y()) * e.impulse;
    }
  }
  check_near(impulse, kG * landing);  // m v, the disc of 1 kg
  const gp::BodyState& falling = r.states[0].back();
  check_near(falling.position.y(), rest + drop - 0.5 * kG * 0.25 * landing * landing);
  const gp::BodyState& stopped = r.states[1].back();
  check_near(stopped.position.x(), 0.0);
  check_near(stopped.position.y(), rest);
  check_near(stopped.velocity.norm(), 0.0);
  for (std::size_t b = 1; b + 1 < scene.bodies.size(); ++b) {
    INFO(scene.bodies[b].name);
    check_near(r.states[1][b].position.x(), scene.bodies[b].position.x());
    check_near(r.states[1][b].position.y(), scene.bodies[b].position.y());
    check_near(r.states[1][b].velocity.norm(), 0.0);
  }
  CHECK(r.largest_drift <= kDrift);
}

}  // namespace test_oracle_contact_scenes
}  // namespace
