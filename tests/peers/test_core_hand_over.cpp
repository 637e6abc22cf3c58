// The bench's measure of how long the two cores take to hand a cache line to each other
// (core_hand_over.hpp): the summary of given rounds, computed by hand, and a measurement that
// ends with times a machine can have.
#include <catch2/catch.hpp>

#include <stdexcept>

#include "verification/bench/core_hand_over.hpp"

namespace {
namespace test_core_hand_over {

TEST_CASE("The hand-over is the median of the rounds, with their least and most",
          "[NFR:Performance]") {
  const gp::bench::HandOver h = gp::bench::hand_over({520.0, 480.0, 2760.0, 930.0});
  CHECK(h.median_ns == Approx(725.0));  // (520 + 930) / 2
  CHECK(h.least_ns == Approx(480.0));
  CHECK(h.most_ns == Approx(2760.0));
  CHECK(h.rounds == 4);
  CHECK_THROWS_AS(gp::bench::hand_over({}), std::invalid_argument);
}

TEST_CASE("Measuring the hand-over runs the rounds and says what it found", "[NFR:Performance]") {
  const gp::bench::HandOver h = gp::bench::measure_hand_over(3, 1000);
  CHECK(h.rounds == 3);
  // A round trip is two writes seen by the other thread: more than a nanosecond on any machine,
  // and under the millisecond the yields of a machine of one core would take at most.
  CHECK(h.least_ns > 1.0);
  CHECK(h.most_ns < 1e6);
  CHECK(h.least_ns <= h.median_ns);
  CHECK(h.median_ns <= h.most_ns);
  const std::string line = gp::bench::describe("now", h);
  CHECK(line.rfind("Two cores now: a cache line written in turn by two threads", 0) == 0);
  CHECK(line.find("3 rounds") != std::string::npos);
}

}  // namespace test_core_hand_over
}  // namespace
