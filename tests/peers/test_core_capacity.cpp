// The bench's measure of what the second core gives at the time of a run (core_capacity.hpp):
// the arithmetic from given times, computed by hand, and a measurement that ends.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "verification/bench/core_capacity.hpp"

namespace {
namespace test_core_capacity {

TEST_CASE("Two copies at one's speed are two cores, and one after the other is one",
          "[NFR:Performance]") {
  // Both copies as fast as one alone: 2 runs' work in 1 run's time.
  CHECK(gp::bench::cores_at_once({0.5, 0.5, 0.5}) == Approx(2.0));
  // The second copy starts only when the first ends (one core): 1.0 and 1.0 − 0.5 = 0.5 s more.
  CHECK(gp::bench::cores_at_once({0.5, 0.5, 1.0}) == Approx(1.0));
  // Seen on this machine: one copy kept its speed (0.51 s), the other took 0.78 s, a run alone
  // 0.49 s. Work together, in runs: 2 − 0.27 / 0.49 = 1.44898; over 0.51 / 0.49 = 1.04082 runs'
  // time: 1.39216.
  CHECK(gp::bench::cores_at_once({0.49, 0.78, 0.51}) == Approx(1.39216).epsilon(1e-5));
}

TEST_CASE("The capacity is the median of the rounds, with their least and most",
          "[NFR:Performance]") {
  // Rounds of 2, 1 and 1.39216 cores; runs alone 0.5, 0.5 and 0.49 s (median 0.5 s).
  const gp::bench::CoreCapacity c =
      gp::bench::core_capacity({{0.5, 0.5, 0.5}, {0.5, 1.0, 0.5}, {0.49, 0.51, 0.78}});
  CHECK(c.median == Approx(1.39216).epsilon(1e-5));
  CHECK(c.least == Approx(1.0));
  CHECK(c.most == Approx(2.0));
  CHECK(c.alone_ms == Approx(500.0));
  CHECK(c.rounds == 3);
  CHECK_THROWS_AS(gp::bench::core_capacity({}), std::invalid_argument);
}

TEST_CASE("Measuring the capacity runs the rounds and says what it found", "[NFR:Performance]") {
  const gp::bench::Workload w{"free10", gp::bench::free_fall(10), 20, std::nullopt};
  const gp::bench::CoreCapacity c = gp::bench::measure_core_capacity(w, 2);
  CHECK(c.rounds == 2);
  CHECK(c.alone_ms > 0.0);
  CHECK(std::isfinite(c.median));
  CHECK(c.least <= c.median);
  CHECK(c.median <= c.most);
  const std::string line = gp::bench::describe("now", w, c);
  CHECK(line.rfind("Two cores now: two runs of free10 (ours, one thread each)", 0) == 0);
  CHECK(line.find("2 rounds") != std::string::npos);
}

}  // namespace test_core_capacity
}  // namespace
