#pragma once
// How much the machine's second core gives at the time of a run. A virtual machine's cores may be
// shared with work out of its sight: then two copies of a one-thread run, started together, do
// not both keep the speed of one alone, and no engine's two threads can be twice as fast as one.
// The bench measures it at its start and end, so that its thread speed-ups can be read against it.

#include <cstddef>
#include <string>
#include <vector>

#include "verification/bench/workloads.hpp"

namespace gp::bench {

/// One round: a run alone, then two copies of it at once [s].
struct CapacityRound {
  double alone;
  double first, second;  ///< each copy's time, started together
};

/// The cores' worth of work done while both copies ran: each copy does the work of one run alone
/// (`alone` s at one core's speed); when the faster ends, the slower's rest is done at one core's
/// speed too, so the work done together, in runs, is 2 − (slower − faster) / alone, over the
/// faster's time in runs, faster / alone. 2: both cores kept their speed; 1: none was gained;
/// above 2 where the machine was slower for the run alone than for the two.
double cores_at_once(const CapacityRound& round);

/// The median of cores_at_once over `rounds` (not empty), with the least and the most.
struct CoreCapacity {
  double median, least, most;
  double alone_ms;  ///< median of the runs alone
  std::size_t rounds;
};
CoreCapacity core_capacity(const std::vector<CapacityRound>& rounds);

/// Times `w` in ours on one thread alone, then as two copies at once on two threads started
/// together, `rounds` times one after the other.
CoreCapacity measure_core_capacity(const Workload& w, int rounds);

/// A line of the bench's output: when (`moment`), the workload, and what `c` found.
std::string describe(const std::string& moment, const Workload& w, const CoreCapacity& c);

}  // namespace gp::bench
