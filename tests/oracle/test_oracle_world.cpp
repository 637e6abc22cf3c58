// The oracle's world (verification/oracle/model): bodies placed at their centres of mass as the
// engine reports them, and the applied accelerations against closed forms (IM:transMot,
// IM:rotMot, DD:torque, TM:UniversalGravLaw).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <vector>

#include "engine/scene/scene_space.hpp"
#include "scene/scene.hpp"
#include "verification/oracle/model/applied_forces.hpp"
#include "verification/oracle/model/world.hpp"

using Catch::Detail::Approx;
using gp::BodyDef;
using gp::BodyType;
using gp::Shape;
using gp::Vec2;
namespace oracle = gp::oracle;

namespace {
namespace test_oracle_world {

constexpr double kPi = std::numbers::pi;

gp::Scene scene_of(std::vector<BodyDef> bodies, const Vec2& gravity = Vec2::Zero()) {
  gp::Scene scene{{}, 0.01, 1.0, 0.01, std::move(bodies)};
  scene.settings.gravity = gravity;
  return scene;
}

BodyDef body(const std::string& name, BodyType type, std::vector<gp::ShapeDef> shapes) {
  BodyDef def;
  def.name = name;
  def.type = type;
  def.shapes = std::move(shapes);
  return def;
}

struct Accelerations {
  std::vector<Vec2> linear;
  std::vector<double> angular;
};

Accelerations accelerations(const oracle::World& world, std::vector<oracle::Motion> motion = {}) {
  if (motion.empty()) {
    for (const auto& b : world.bodies) motion.push_back(b.initial);
  }
  Accelerations a{std::vector<Vec2>(motion.size()), std::vector<double>(motion.size())};
  oracle::applied_accelerations(world, motion, a.linear, a.angular);
  return a;
}

TEST_CASE("Oracle world: a body's position is its centre of mass, as the engine reports it",
          "[oracle][model]") {
  SECTION("docs/scene-format.md: a body at [0, 10] with a circle centred at [1, 0] is at [1, 10]") {
    BodyDef ball = body("ball", BodyType::Dynamic, {{Shape::circle(0.5, Vec2(1.0, 0.0))}});
    ball.position = Vec2(0.0, 10.0);
    const oracle::World world = oracle::build_world(scene_of({ball}));
    CHECK((world.bodies[0].initial.position - Vec2(1.0, 10.0)).norm() == 0.0);
    // The hull is about the centre of mass: the disc's centre is at the CoM.
    CHECK(world.bodies[0].hulls[0].vertices[0].norm() == 0.0);
    CHECK(world.bodies[0].hulls[0].radius == 0.5);
  }
  SECTION("every shipped scene: positions, angles, velocities and inverse masses of the engine") {
    for (const auto& entry : std::filesystem::directory_iterator(GP_SOURCE_DIR "/scenes")) {
      if (entry.path().extension() != ".json") continue;
      const gp::Scene scene = gp::load_scene(entry.path());
      const oracle::World world = oracle::build_world(scene);
      const auto space = gp::build_space(scene);
      for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        const oracle::RigidBody& b = world.bodies[i];
        const gp::BodyState s = space->state(static_cast<gp::BodyId>(i));
        INFO(entry.path().filename().string() << ", body " << b.name);
        // Measured equal; 1e-13 m allows the polygon integrals' other order of terms (a few
        // ulps of the scenes' 100 m).
        CHECK((b.initial.position - s.position).norm() <= 1e-13);
        CHECK(b.initial.angle == s.angle);
        CHECK(b.initial.velocity == s.velocity);
        CHECK(b.initial.angular_velocity == s.angular_velocity);
        const double engine_inverse_mass = 1.0 / space->mass(static_cast<gp::BodyId>(i));
        CHECK(b.inverse_mass == Approx(engine_inverse_mass).epsilon(1e-15));
        const double engine_inverse_moment = 1.0 / space->moment(static_cast<gp::BodyId>(i));
        CHECK(b.inverse_moment == Approx(engine_inverse_moment).epsilon(1e-14));
      }
    }
  }
}

TEST_CASE("Oracle world: applied accelerations against closed forms", "[oracle][model]") {
  SECTION("gravity alone: g on dynamic bodies, nothing on static and kinematic ones") {
    BodyDef ball = body("ball", BodyType::Dynamic, {{Shape::circle(0.5)}});
    BodyDef ground = body("ground", BodyType::Static, {{Shape::box(10.0, 1.0)}});
    BodyDef paddle = body("paddle", BodyType::Kinematic, {{Shape::box(1.0, 0.2)}});
    paddle.velocity = Vec2(1.0, 0.0);
    const oracle::World world =
        oracle::build_world(scene_of({ball, ground, paddle}, Vec2(0.0, -9.81)));
    const Accelerations a = accelerations(world);
    CHECK(a.linear[0] == Vec2(0.0, -9.81));
    CHECK(a.linear[1] == Vec2::Zero());
    CHECK(a.linear[2] == Vec2::Zero());
    CHECK(a.angular == std::vector<double>{0.0, 0.0, 0.0});
    CHECK(world.bodies[1].inverse_mass == 0.0);
    CHECK(world.bodies[2].inverse_moment == 0.0);
    CHECK(world.bodies[2].initial.velocity == Vec2(1.0, 0.0));
  }
  SECTION("a force at a body-frame point: a = F/m, τ = r × F with r turned with the body") {
    // A 2 m × 2 m box of density 1: m = 4 kg, I = m (2² + 2²) / 12 = 8/3 kg·m².
    BodyDef box = body("box", BodyType::Dynamic, {{Shape::box(2.0, 2.0)}});
    box.force = Vec2(0.0, 3.0);
    box.force_point = Vec2(1.0, 0.0);
    box.torque = 0.5;
    const oracle::World world = oracle::build_world(scene_of({box}, Vec2(0.0, -1.0)));
    CHECK(world.bodies[0].mass == Approx(4.0).epsilon(1e-15));
    CHECK(world.bodies[0].moment == Approx(8.0 / 3.0).epsilon(1e-15));
    oracle::Motion state = world.bodies[0].initial;
    Accelerations a = accelerations(world, {state});
    CHECK(a.linear[0].x() == 0.0);
    CHECK(a.linear[0].y() == Approx(-1.0 + 3.0 / 4.0).epsilon(1e-15));
    // Arm (1, 0), F = (0, 3): τ = 1·3 − 0·0 = 3 N·m, plus the constant 0.5 N·m.
    CHECK(a.angular[0] == Approx((3.0 + 0.5) / (8.0 / 3.0)).epsilon(1e-15));
    // Turned by a quarter turn the arm is (0, 1), parallel to F: only the constant torque.
    state.angle = 0.5 * kPi;
    a = accelerations(world, {state});
    CHECK(a.angular[0] == Approx(0.5 / (8.0 / 3.0)).epsilon(1e-14));
  }
  SECTION("the arm is measured from the centre of mass, not the body origin") {
    // A disc centred at (1, 0) of the body frame: a force at the body origin acts 1 m off the CoM.
    BodyDef disc = body("disc", BodyType::Dynamic, {{Shape::circle(1.0, Vec2(1.0, 0.0))}});
    disc.force = Vec2(0.0, 2.0);
    disc.force_point = Vec2::Zero();
    const oracle::World world = oracle::build_world(scene_of({disc}));
    const double moment = 0.5 * kPi * 1.0;  // m r² / 2 with m = π
    CHECK(accelerations(world).angular[0] == Approx(-2.0 / moment).epsilon(1e-15));
  }
  SECTION("pairwise gravitation: a₁ = G m₂ / d² towards body 2, and the reaction on body 2") {
    BodyDef one = body("one", BodyType::Dynamic, {});
    one.mass = 3e11;
    BodyDef two = body("two", BodyType::Dynamic, {});
    two.mass = 1e11;
    two.position = Vec2(2.0, 0.0);
    BodyDef wall = body("wall", BodyType::Static, {{Shape::box(1.0, 1.0)}});
    wall.position = Vec2(0.0, 5.0);
    gp::Scene scene = scene_of({one, two, wall});
    scene.settings.G = 6.674e-11;
    const Accelerations a = accelerations(oracle::build_world(scene));
    CHECK(a.linear[0].x() == Approx(6.674e-11 * 1e11 / 4.0).epsilon(1e-15));
    CHECK(a.linear[1].x() == Approx(-6.674e-11 * 3e11 / 4.0).epsilon(1e-15));
    // A static body neither pulls nor is pulled (scene format: between dynamic bodies).
    CHECK(a.linear[0].y() == 0.0);
    CHECK(a.linear[2] == Vec2::Zero());
  }
}

}  // namespace test_oracle_world
}  // namespace
