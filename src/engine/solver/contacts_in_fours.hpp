#pragma once
// How the kernels that take a colour's or a level's contacts four at a time (single_point_lanes,
// two_point_lanes) are run over a stretch of contacts.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>

#include "engine/solver/contact_set.hpp"

namespace gp {

/// A kernel: one pass of solve_contact_once over the n ≤ 4 contacts from `ids` on, on the
/// velocities of the state; returns the largest value solve_contact_once would.
using FourContactsKernel = double (*)(ContactSet& set, const std::uint32_t* ids, std::size_t n,
                                      const BodyInertia& inertia, MotionState& s);

/// The largest of what `Kernel` returns over `contacts`, four at a time (the last run four or
/// fewer), called directly. A build without AVX2 has no kernel (nullptr): `who` then throws a
/// logic_error.
template <FourContactsKernel Kernel>
double solve_in_fours(const char* who, [[maybe_unused]] ContactSet& set,
                      [[maybe_unused]] std::span<const std::uint32_t> contacts,
                      [[maybe_unused]] const BodyInertia& inertia,
                      [[maybe_unused]] MotionState& s) {
  if constexpr (Kernel == nullptr) {
    throw std::logic_error(std::string(who) + ": four lanes need AVX2");
  } else {
    double largest = 0.0;
    for (std::size_t done = 0; done < contacts.size(); done += 4) {
      largest =
          std::max(largest, Kernel(set, contacts.data() + done,
                                   std::min<std::size_t>(4, contacts.size() - done), inertia, s));
    }
    return largest;
  }
}

}  // namespace gp
