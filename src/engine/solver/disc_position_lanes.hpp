#pragma once
// The position passes over contacts between two discs, each about its body's centre of mass, four
// at a time where the CPU has AVX2: such a contact's deepest points stay along the normal however
// the discs turn, so a pass needs no rotation, and pushing along the normal turns neither disc.

#include <cstdint>
#include <span>

#include "engine/lanes.hpp"
#include "engine/solver/contact_set.hpp"

namespace gp {

/// Whether `point`'s contact is one that correct_centred_discs takes: both of its anchors are
/// centred discs (AnchorKind::kCentredDisc).
inline bool centred_discs(const ContactPointState& point) {
  return point.anchor_a == AnchorKind::kCentredDisc && point.anchor_b == AnchorKind::kCentredDisc;
}

/// What a position pass reads besides the state it moves: the bodies' inertias and the slop [m].
struct DiscPositionInput {
  const BodyInertia& inertia;
  double slop;
};

/// One position pass of PositionCorrection over `contacts` (indices into `set` of one-point
/// contacts between centred discs, no two of which share a movable body), four at a time; returns
/// whether one of them overlapped by more than two slops. Each lane runs the pass's operations
/// in its order, compiled for AVX2 alone, so positions and angles are the same to the bit as one
/// at a time; the bodies' inverse moments are finite, so that no disc turns (0 · I⁻¹ = 0). Only
/// where four_lanes().
bool correct_centred_discs(const ContactSet& set, std::span<const std::uint32_t> contacts,
                           const DiscPositionInput& in, MotionState& s);

}  // namespace gp
