#pragma once
// Passes of sequential impulses over two-point contacts (a box's edge on another's) that share no
// movable body, a colour's or a level's, four at a time where the CPU has AVX2: each as it would
// be solved alone, its two points' normal constraints together (the block solver), each field of
// four contacts in one 256-bit register.

#include <cstdint>
#include <span>

#include "engine/lanes.hpp"
#include "engine/solver/contact_set.hpp"

namespace gp {

/// One pass of solve_contact_once over `contacts` (indices into `set`), two-point contacts no two
/// of which share a movable body, after their effective masses, targets and blocks are set
/// (prepare_contacts), on the velocities of `s`, four at a time; returns the largest value
/// solve_contact_once would. Each lane runs solve_contact_once's operations in its order, its
/// four cases of the block and the one-by-one solve where the block does not serve chosen lane by
/// lane, compiled for AVX2 alone (no fused multiply-add to round differently), so the velocities
/// and impulses are the same to the bit. Only where four_lanes().
double solve_two_points(ContactSet& set, std::span<const std::uint32_t> contacts,
                        const BodyInertia& inertia, MotionState& s);

}  // namespace gp
