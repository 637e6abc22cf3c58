#pragma once
// How the kernels that take a colour's or a level's contacts four at a time (single_point_lanes,
// two_point_lanes) are run over a stretch of contacts.

#include <cstddef>
#include <cstdint>
#include <span>

#include "engine/solver/contact_set.hpp"

namespace gp {

/// A kernel: one pass of solve_contact_once over the n ≤ 4 contacts from `ids` on, on the
/// velocities of the state; returns the largest value solve_contact_once would.
using FourContactsKernel = double (*)(ContactSet& set, const std::uint32_t* ids, std::size_t n,
                                      const BodyInertia& inertia, MotionState& s);

/// The largest of what `kernel` returns over `contacts`, four at a time (the last run four or
/// fewer). A build without AVX2 has no kernel (nullptr): `who` then throws a logic_error.
double solve_in_fours(FourContactsKernel kernel, const char* who, ContactSet& set,
                      std::span<const std::uint32_t> contacts, const BodyInertia& inertia,
                      MotionState& s);

}  // namespace gp
