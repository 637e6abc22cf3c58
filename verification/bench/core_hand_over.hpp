#pragma once
// How long the machine's two cores take to hand memory to each other at the time of a run. The
// threads of one step share its bodies and contacts: what one writes and the other touches next
// travels between the cores' caches, over a distance a virtual machine's host decides and may
// change from minute to minute. Two copies of a run (core_capacity.hpp) share nothing and do not
// see it; the bench measures both, so that its thread speed-ups can be read against them.

#include <string>
#include <vector>

namespace gp::bench {

/// The round trips of a cache line between two threads, one round each: the mean time [ns] for
/// the line to go to the other thread and come back.
struct HandOver {
  double median_ns, least_ns, most_ns;
  int rounds;
};

/// The median, least and most of `round_trips_ns` (not empty), one per round.
HandOver hand_over(const std::vector<double>& round_trips_ns);

/// `rounds` rounds of `trips` round trips of one cache line between this thread and another, each
/// spinning until the other has written it.
HandOver measure_hand_over(int rounds, int trips);

/// A line of the bench's output: when (`moment`) and what `h` found.
std::string describe(const std::string& moment, const HandOver& h);

}  // namespace gp::bench
