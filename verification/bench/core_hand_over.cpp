#include "verification/bench/core_hand_over.hpp"

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "verification/bench/figures.hpp"
#include "verification/bench/formatted.hpp"

namespace gp::bench {

HandOver hand_over(const std::vector<double>& round_trips_ns) {
  if (round_trips_ns.empty()) throw std::invalid_argument("hand_over: no rounds");
  const Spread spread = spread_of(round_trips_ns);
  return {spread.median, spread.min, spread.max, static_cast<int>(round_trips_ns.size())};
}

namespace {

// Waits until `line` holds `value`: spinning, as a step's threads do, but yielding now and then,
// so that on a machine of one core the other thread gets to write it.
void wait_for(const std::atomic<int>& line, int value) {
  for (int spins = 1; line.load(std::memory_order_acquire) != value; ++spins) {
    if (spins % 4096 == 0) std::this_thread::yield();
  }
}

}  // namespace

HandOver measure_hand_over(int rounds, int trips) {
  // A line of its own, so that nothing else the threads touch moves with it.
  struct alignas(64) Line {
    std::atomic<int> turn{0};
  };
  std::vector<double> measured;
  for (int r = 0; r < rounds; ++r) {
    Line line;
    // The other thread answers each 1 with a 0; this one times the trips from its first 1.
    std::thread other([&line, trips] {
      for (int i = 0; i < trips; ++i) {
        wait_for(line.turn, 1);
        line.turn.store(0, std::memory_order_release);
      }
    });
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < trips; ++i) {
      line.turn.store(1, std::memory_order_release);
      wait_for(line.turn, 0);
    }
    const std::chrono::duration<double, std::nano> took = std::chrono::steady_clock::now() - start;
    other.join();
    measured.push_back(took.count() / trips);
  }
  return hand_over(measured);
}

std::string describe(const std::string& moment, const HandOver& h) {
  return "Two cores " + moment +
         ": a cache line written in turn by two threads went to the other core and back in " +
         formatted("%.0f", h.median_ns) + " ns (least " + formatted("%.0f", h.least_ns) +
         ", most " + formatted("%.0f", h.most_ns) + ", " + std::to_string(h.rounds) +
         " rounds): what a step's threads pay for each line of bodies or contacts that one writes "
         "and the other touches next";
}

}  // namespace gp::bench
