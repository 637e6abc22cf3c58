#pragma once
// Passes of sequential impulses over the one-point contacts of colours four at a time, where the
// CPU has AVX2: the contacts of a colour share no movable body, so each is solved as it would be
// alone, and each field of four contacts goes into one 256-bit register. For the passes to load
// them so, the fields are copied out once a step, each into an array of its own.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/lanes.hpp"
#include "engine/solver/contact_set.hpp"

namespace gp {

/// The fields a pass reads of the one-point contacts of a run of colours, each field in an array
/// of its own, by the contact's entry in that run, kept between steps so that a step does not
/// allocate. Only where four_lanes().
class SinglePointLanes {
 public:
  /// Copies out the fields of the one-point contacts among `entries` (indices into `set`), after
  /// their effective masses and targets are set (prepare_contacts), and their bodies' inverse
  /// inertias.
  void pack(std::span<const std::uint32_t> entries, const ContactSet& set,
            const BodyInertia& inertia);

  /// How many of the `count` entries from `first` on are one-point contacts before the first that
  /// is not.
  std::size_t leading_single_points(std::size_t first, std::size_t count) const;

  /// One pass of solve_contact_once over the `count` entries from `first` on, one-point contacts
  /// no two of which share a movable body, on the velocities of `s`, four at a time; returns the
  /// largest value solve_contact_once would. Each lane runs solve_contact_once's operations in
  /// its order, compiled for AVX2 alone (no fused multiply-add to round differently), so the
  /// velocities and impulses are the same to the bit. Only where four_lanes().
  double solve(std::size_t first, std::size_t count, MotionState& s);

  /// The impulses the passes accumulated, back into the points of `set` they were packed from.
  void unpack(ContactSet& set) const;

  /// How the passes take a colour's one-point contacts, for --explain: "four at a time (AVX2)"
  /// where four_lanes(), else "one at a time".
  static const char* name();

 private:
  std::vector<double> fields_;          // the fields (single_point_lanes.cpp), array after array,
                                        // an entry of each array per entry of contact_
  std::vector<std::uint32_t> contact_;  // per entry: its index in the set
  std::vector<std::uint8_t> single_;    // per entry: 1 for a one-point contact (packed)
  std::vector<BodyId> body_a_, body_b_;
};

}  // namespace gp
