// The oracle's time-stepping reference (Moreau–Jean, stepping/) against closed forms where an
// impact falls inside a step (a disc dropped with C_R = 0, an elastic bounce), and against the
// event-driven oracle on a box tipping over a step, where it converges at first order. Its exact
// cases (uniform accelerations: a block sliding, a disc rolling, a stack at rest) are in
// test_oracle_contact_scenes.cpp.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "oracle_scenes.hpp"
#include "scene/scene.hpp"
#include "verification/oracle/oracle.hpp"

using gp::Vec2;
using gp::verification::OracleMethod;
using gp::verification::OracleOptions;
using gp::verification::OracleResult;
using gp::verification::run_oracle;

namespace {
namespace test_oracle_time_stepping {

constexpr double kG = 9.81;
constexpr double kRadius = 0.5;

// A disc of radius 0.5 m and 1 kg, its centre `drop` m above its resting height on a static
// ground, both surfaces of restitution `restitution`.
gp::Scene dropped_disc(double drop, double restitution) {
  return gp::test::scene_of(
      gp::test::with_gravity(kG),
      {gp::test::ground(restitution),
       gp::test::disc("disc", {0.0, kRadius + drop}, Vec2::Zero(), kRadius, 1.0, restitution)});
}

OracleOptions stepping(double h) {
  OracleOptions options;
  options.method = OracleMethod::TimeStepping;
  options.step = h;
  return options;
}

// Every step's end from 0 to `end` [s].
std::vector<double> every_step(double h, double end) {
  std::vector<double> times;
  for (long k = 0; k * h <= end + 1e-12; ++k) times.push_back(static_cast<double>(k) * h);
  return times;
}

// m: the largest distance between the bodies' centres in `a` and `b`, over every instant.
double largest_position_difference(const OracleResult& a, const OracleResult& b) {
  double d = 0.0;
  for (std::size_t k = 0; k < a.states.size(); ++k) {
    for (std::size_t i = 0; i < a.states[k].size(); ++i) {
      d = std::max(d, (a.states[k][i].position - b.states[k][i].position).norm());
    }
  }
  return d;
}

TEST_CASE("oracle time-stepping: a disc dropped with C_R = 0 rests on the ground, first order",
          "[oracle][stepping]") {
  // Free flight is exact (positions by the trapezoid under constant gravity); the landing step is
  // the first whose gap predicted at mid-step is closed, so it starts within h/2 of t_c and the
  // disc is at rest a step later, sunk by less than h v_c (what it travels in that step).
  const double drop = 2.0, landing = std::sqrt(2.0 * drop / kG), arrival = kG * landing;
  const gp::Scene scene = dropped_disc(drop, 0.0);
  for (const double h : {4e-3, 2e-3, 1e-3}) {
    INFO("h = " << h);
    const std::vector<double> times = every_step(h, 1.0);
    const OracleResult r = run_oracle(scene, times, stepping(h));
    std::size_t rest = 1;
    while (rest < times.size() && r.states[rest][1].velocity.norm() > 1e-12) ++rest;
    REQUIRE(rest < times.size());
    CHECK(times[rest] - landing >= 0.0);
    CHECK(times[rest] - landing <= 1.5 * h);
    const double sunk = kRadius - r.states[rest][1].position.y();
    CHECK(sunk >= 0.0);
    CHECK(sunk <= h * arrival);
    CHECK(r.states.back()[1].position.y() == r.states[rest][1].position.y());
    CHECK(r.largest_drift <= h * arrival);
  }
}

TEST_CASE("oracle time-stepping: an elastic bounce (C_R = 1) keeps its energy",
          "[oracle][stepping]") {
  // Free flight keeps ½ v² + g y exactly; the landing step reverses the arrival speed where the
  // disc stands (Newton's law with e = 1 at v⁻, positions moved by h (v⁻ + v⁺) / 2 = 0). So the
  // energy is kept to round-off, while each bounce turns up to h v_c / 2 above the ground or
  // h v_c below it, up to 2 h early or late: the height departs from the closed form by at most
  // 2 v_c h a bounce (measured 1.35 v_c h), and v_c h within the step under way.
  const double drop = 1.0, landing = std::sqrt(2.0 * drop / kG), arrival = kG * landing;
  const gp::Scene scene = dropped_disc(drop, 1.0);
  const double end = 3.0;
  for (const double h : {2e-3, 1e-3}) {
    INFO("h = " << h);
    const std::vector<double> times = every_step(h, end);
    const OracleResult r = run_oracle(scene, times, stepping(h));
    const double energy = kG * (kRadius + drop);  // J/kg
    for (std::size_t k = 0; k < times.size(); ++k) {
      const gp::BodyState& s = r.states[k][1];
      INFO("t = " << times[k]);
      // Exact in exact arithmetic; 1e-12 of it is a thousand steps' round-off.
      CHECK(std::abs(0.5 * s.velocity.squaredNorm() + kG * s.position.y() - energy) <=
            1e-12 * energy);
      // The closed form: apexes at 0, 2 t_c, 4 t_c, …, landings at t_c, 3 t_c, …
      const double phase = std::fmod(times[k], 2.0 * landing);
      const double fall = std::min(phase, 2.0 * landing - phase);
      const double y = kRadius + drop - 0.5 * kG * fall * fall;
      const double bounces = std::floor((times[k] + landing) / (2.0 * landing));
      CHECK(std::abs(s.position.y() - y) <= (2.0 * bounces + 1.0) * arrival * h);
    }
  }
}

TEST_CASE(
    "oracle time-stepping: a box tipping over a step converges to the event-driven oracle "
    "at first order",
    "[oracle][stepping]") {
  // step_tip while the box turns about the step's corner (to 0.35 s): the event-driven oracle
  // holds the contact to 1e-12 m; time-stepping's error is first order in h.
  gp::Scene scene = gp::load_scene(std::string(GP_SOURCE_DIR) + "/scenes/step_tip.json");
  std::vector<double> times;
  for (int k = 0; k <= 14; ++k) times.push_back(0.025 * k);
  const OracleResult events = run_oracle(scene, times);
  std::vector<double> errors;
  for (const double h : {2e-3, 1e-3, 5e-4}) {
    errors.push_back(largest_position_difference(run_oracle(scene, times, stepping(h)), events));
    INFO("h = " << h << ": " << errors.back() << " m");
    // Measured 0.157 h to 0.167 h.
    CHECK(errors.back() <= 0.2 * h);
  }
  const double order = std::log2(errors.front() / errors.back()) / 2.0;
  INFO("observed order " << order);
  CHECK(order >= 0.9);
  CHECK(order <= 1.1);
}

}  // namespace test_oracle_time_stepping
}  // namespace
