#pragma once
// One pass of sequential impulses over one-point contacts of a colour, four at a time where the
// CPU has AVX2: the contacts of a colour share no movable body, so each is solved as it would be
// alone, and each field of the four goes into one 256-bit register.

#include <cstdint>
#include <span>

#include "engine/lanes.hpp"
#include "engine/solver/contact_set.hpp"

namespace gp {

/// solve_contact_once over each of `contacts` (indices into `set` of one-point contacts no two of
/// which share a movable body), four at a time when `lanes` is kFour (only where widest_lanes()
/// is), one at a time otherwise; returns the largest value solve_contact_once returns for them.
/// Each lane runs solve_contact_once's operations in its order, compiled for AVX2 alone (no fused
/// multiply-add to round differently), so the velocities and impulses are the same to the bit
/// either way.
double solve_single_points(ContactSet& set, std::span<const std::uint32_t> contacts,
                           const BodyInertia& inertia, MotionState& s, Lanes lanes);

/// How solve_single_points takes them with `lanes`, for --explain: "four at a time (AVX2)".
const char* single_point_lanes_name(Lanes lanes);

}  // namespace gp
