// The run the viewer records (verification/viewer): its frames are the instants of simulate, its
// energies are what hand computation gives (conserved in free flight, reduced by C_R² at a
// bounce), its impacts carry the impulse of GD:impulse, and its resting contacts hold the stack.
#include <catch2/catch.hpp>
#include <cmath>

#include "engine/scene/scene_space.hpp"
#include "scene/scene.hpp"
#include "verification/viewer/recording.hpp"

namespace {
namespace test_recording {

constexpr double kPi = 3.14159265358979323846;

struct Recorded {
  gp::Scene scene;
  std::unique_ptr<gp::Space> space;
  gp::verification::Recording recording;
};

Recorded record(const std::string& file, const gp::SceneOverrides& overrides = {}) {
  Recorded r{gp::load_scene(std::string(GP_SOURCE_DIR) + "/scenes/" + file, overrides), {}, {}};
  r.space = gp::build_space(r.scene);
  r.recording = gp::verification::record_run(*r.space, r.scene);
  return r;
}

TEST_CASE("The viewer's energies of the bouncing ball are the hand-computed ones",
          "[via:DD:kEnergy][via:DD:potEnergy]") {
  const auto r = record("bouncing_ball.json", {std::nullopt, std::nullopt, 2.5, std::nullopt});
  const auto& frames = r.recording.frames;
  REQUIRE(frames.size() == 151);  // every 1/60 s from 0 to 2.5 s, as simulate writes them
  const double m = kPi * 0.5 * 0.5, g = 9.81;
  const double E0 = m * g * 10.0;  // at rest at 10 m
  const double t_c = std::sqrt(2.0 * 9.5 / g);
  // After the bounce the kinetic energy at the ground, E0 − m g 0.5, is scaled by C_R² = 0.64.
  const double E1 = m * g * 0.5 + 0.64 * (E0 - m * g * 0.5);
  for (const auto& f : frames) {
    const auto& s = f.states[1];
    const auto& q = f.quantities[1];
    CHECK(q.translational_energy == Approx(0.5 * m * s.velocity.squaredNorm()).margin(1e-12));
    CHECK(q.rotational_energy == 0.0);
    CHECK(q.potential_energy == Approx(m * g * s.position.y()));
    CHECK(f.totals.energy() == Approx(q.translational_energy + q.potential_energy));
    CHECK(f.quantities[0].potential_energy == 0.0);  // the static ground carries none
    if (f.time < t_c) CHECK(f.totals.energy() == Approx(E0).epsilon(1e-12));
    if (f.time > t_c + 0.05) CHECK(f.totals.energy() == Approx(E1).epsilon(1e-9));
  }
}

TEST_CASE("The viewer records the first bounce with the impulse of GD:impulse",
          "[via:GD:impulse][via:IM:col2D]") {
  const auto r = record("bouncing_ball.json", {std::nullopt, std::nullopt, 2.0, std::nullopt});
  REQUIRE(r.recording.impacts.size() == 1);
  const gp::Impact& impact = r.recording.impacts[0];
  const double g = 9.81, m = kPi * 0.5 * 0.5;
  // j = (1 + C_R) m |v| against a static ground, |v| = √(2 g 9.5) at t_c = √(2·9.5/g).
  CHECK(impact.time == Approx(std::sqrt(2.0 * 9.5 / g)).epsilon(1e-10));
  CHECK(impact.impulse == Approx(1.8 * m * std::sqrt(2.0 * g * 9.5)).epsilon(1e-10));
  CHECK(std::abs(impact.normal.y()) == Approx(1.0));
  CHECK(impact.point.y() == Approx(0.0).margin(1e-9));
}

TEST_CASE("The viewer's resting contacts of a box stack carry its weight",
          "[FR:Determine-Collision-Response-Over-Time]") {
  // The bottom row of the pyramid on the ground, settled after 3 s: the ground's contact
  // impulses over the last step (1/60 s) add up to the weight of all 210 boxes times the step.
  const auto r = record("pyramid20.json", {std::nullopt, std::nullopt, 3.0, std::nullopt});
  const auto& last = r.recording.frames.back();
  double on_ground = 0.0;
  int points = 0;
  for (const auto& c : last.contacts) {
    CHECK(c.impulse > 0.0);
    if (c.body_a == 0 || c.body_b == 0) on_ground += c.impulse, ++points;
  }
  CHECK(points >= 20);  // the bottom row's 20 boxes, one or two points each
  CHECK(on_ground == Approx(210 * 1.0 * 9.81 / 60.0).epsilon(1e-3));
}

TEST_CASE("The viewer's rotational energy of the spinning box is I omega squared over 2",
          "[via:DD:kEnergy]") {
  const auto r = record("spinning_box.json");
  const double I = 1.0 / 6.0;
  for (const auto& f : r.recording.frames) {
    const double omega = 3.0 * f.time;  // α = τ / I = 3 rad/s²
    CHECK(f.quantities[0].rotational_energy == Approx(0.5 * I * omega * omega).margin(1e-12));
    CHECK(f.quantities[0].translational_energy == 0.0);
    CHECK(f.totals.angular_momentum == Approx(I * omega).margin(1e-12));
  }
}

}  // namespace test_recording
}  // namespace
