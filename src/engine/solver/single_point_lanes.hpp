#pragma once
// Passes of sequential impulses over one-point contacts that share no movable body (a level's or
// a colour's) four at a time, where the CPU has AVX2: each is solved as it would be alone, and
// each field of four contacts goes into one 256-bit register, transposed from where the contact
// set keeps the contacts and their points.

#include <cstdint>
#include <span>

#include "engine/lanes.hpp"
#include "engine/solver/contact_set.hpp"

namespace gp {

/// One pass of solve_contact_once over `contacts` (indices into `set`), one-point contacts no two
/// of which share a movable body, after their effective masses and targets are set
/// (prepare_contacts), on the velocities of `s`, four at a time; returns the largest value
/// solve_contact_once would. Each lane runs solve_contact_once's operations in its order,
/// compiled for AVX2 alone (no fused multiply-add to round differently), so the velocities and
/// impulses are the same to the bit. Only where four_lanes().
double solve_single_points(ContactSet& set, std::span<const std::uint32_t> contacts,
                           const BodyInertia& inertia, MotionState& s);

/// How the velocity passes take a level's or a colour's one-point contacts, and a colour's
/// two-point ones (solve_two_points), for --explain: "four at a time (AVX2)" where four_lanes(),
/// else "one at a time".
const char* contact_lanes_name();

}  // namespace gp
