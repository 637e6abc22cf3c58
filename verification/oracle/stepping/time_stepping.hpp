#pragma once
// The oracle's reference for piles: Moreau–Jean time-stepping (moreau_jean.hpp) at a fixed step,
// where the event-driven integration meets more events than it can afford (a pile's impacts
// cascade, its contacts open and close thousands of times a second). It is first order in the
// step: a reference is two runs, at h and h/2, whose difference is its own error estimate.

#include <span>
#include <vector>

#include "verification/oracle/contact/active_contact.hpp"

namespace gp::oracle {

struct SteppedRun {
  std::vector<std::vector<Motion>> motions;  ///< every body at each output instant
  long steps = 0;
  double deepest_overlap = 0.0;  ///< m: the largest −g of a contact of an index set
};

/// The bodies of `world` from their initial motions to each of `times` [s, non-decreasing, ≥ 0],
/// watching `pairs`, in steps of at most `step` [s, > 0]: each interval between output instants
/// is cut into equal steps, so that every output instant is reached exactly. Hulls within
/// `tolerance` [m] at mid-step are in contact (index_set).
SteppedRun time_stepping(const World& world, std::span<const HullPair> pairs,
                         std::span<const double> times, double step, double tolerance);

}  // namespace gp::oracle
