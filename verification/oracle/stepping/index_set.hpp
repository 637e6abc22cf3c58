#pragma once
// Which contacts a time step of Moreau–Jean's scheme constrains: its index set, the feature pairs
// whose gap, predicted at mid-step from the gap and its rate at the step's start, is closed.

#include <span>
#include <vector>

#include "verification/oracle/contact/active_contact.hpp"
#include "verification/oracle/contact/contact_kinematics.hpp"

namespace gp::oracle {

/// A contact of the index set with its kinematics at the step's start.
struct StepContact {
  ActiveContact contact;
  ContactKinematics kinematics;
};

/// The contacts among `pairs` of `world` at `motions` (every body's) for a step of `h` [s, > 0]:
/// the nearest feature pairs of each pair of hulls (contact_geometry) whose gap g [m] and rate ġ
/// [m/s] give g + ½ h ġ ≤ `tolerance` [m] (Acary and Brogliato 2008, §10.1: the prediction at
/// θ = ½, with the oracle's contact tolerance, so that bodies touching up to round-off, a disc
/// set on a ramp, are held from the first step rather than falling through one step freely).
std::vector<StepContact> index_set(const World& world, std::span<const HullPair> pairs,
                                   std::span<const Motion> motions, double h, double tolerance);

}  // namespace gp::oracle
