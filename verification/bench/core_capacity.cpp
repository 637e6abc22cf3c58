#include "verification/bench/core_capacity.hpp"

#include <algorithm>
#include <barrier>
#include <exception>
#include <stdexcept>
#include <thread>

#include "verification/bench/figures.hpp"
#include "verification/bench/formatted.hpp"
#include "verification/bench/timed_run.hpp"

namespace gp::bench {

double cores_at_once(const CapacityRound& round) {
  const double faster = std::min(round.first, round.second);
  const double slower = std::max(round.first, round.second);
  return (2.0 - (slower - faster) / round.alone) / (faster / round.alone);
}

CoreCapacity core_capacity(const std::vector<CapacityRound>& rounds) {
  if (rounds.empty()) throw std::invalid_argument("core_capacity: no rounds");
  std::vector<double> cores, alone;
  for (const CapacityRound& r : rounds) {
    cores.push_back(cores_at_once(r));
    alone.push_back(r.alone);
  }
  const Spread spread = spread_of(cores);
  return {spread.median, spread.min, spread.max, 1e3 * median(alone), rounds.size()};
}

CoreCapacity measure_core_capacity(const Workload& w, int rounds) {
  std::vector<CapacityRound> measured;
  for (int i = 0; i < rounds; ++i) {
    CapacityRound round{time_run(w, Engine::Ours).seconds, 0.0, 0.0};
    // Each copy sets its scene up, then both start stepping together. A copy that throws (a state
    // that became non-finite) before it started lets the other go; what either threw is rethrown
    // once both have ended.
    std::barrier start(2);
    const auto copy = [&](double& seconds, std::exception_ptr& failed) {
      bool started = false;
      const AroundSteps together{[&] {
                                   started = true;
                                   start.arrive_and_wait();
                                 },
                                 {}};
      try {
        seconds = time_run(w, Engine::Ours, together).seconds;
      } catch (...) {
        failed = std::current_exception();
        if (!started) start.arrive_and_drop();
      }
    };
    std::exception_ptr failed, failed_other;
    std::thread other([&] { copy(round.second, failed_other); });
    copy(round.first, failed);
    other.join();
    for (const std::exception_ptr& e : {failed, failed_other}) {
      if (e) std::rethrow_exception(e);
    }
    measured.push_back(round);
  }
  return core_capacity(measured);
}

std::string describe(const std::string& moment, const Workload& w, const CoreCapacity& c) {
  return "Two cores " + moment + ": two runs of " + w.name +
         " (ours, one thread each) started together did the work of " +
         formatted("%.2f", c.median) + " runs at once (least " + formatted("%.2f", c.least) +
         ", most " + formatted("%.2f", c.most) + ", " + std::to_string(c.rounds) +
         " rounds; one alone " + formatted("%.1f", c.alone_ms) +
         " ms): the most a second thread could give then";
}

}  // namespace gp::bench
