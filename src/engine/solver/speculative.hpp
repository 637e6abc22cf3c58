#pragma once
// Impacts on bodies that rest on others, handed over to the contact solver by LocalImpacts.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core.hpp"
#include "engine/step/step_context.hpp"

namespace gp {

/// Scratch for solve_speculative, kept by the caller so that a step does not allocate.
struct SpeculativeScratch {
  std::vector<char> reached;          // per body
  std::vector<char> included;         // per resting contact
  std::vector<std::uint32_t> nearby;  // resting contacts solved with the impacts
  std::vector<BodyId> newly;
};

/// Impacts the contact solver takes on after the resting contacts are solved: the speculative
/// contacts' points, still apart at the start of the step of h [s], whose bodies also rest on
/// others (see LocalImpacts). They are solved together with the resting contacts within a few
/// contacts of them for the velocity iterations, and bounce by C_R after; the impulses this adds
/// act from the impact on, so they move the bodies by h × Δv rather than by the resting share,
/// which would leave a fast body overlapping and press the body under it into the ground. A point
/// apart by at most twice its bodies' lag (how far their places trail h × their velocity: g h²/2
/// for a body falling freely) closes its gap by the end of the step; one farther apart is aimed at
/// its gap alone, so that a fast body stops a lag short and lands, slowly, at the next step. The
/// resting contacts are solved in their own order (by pair of shapes);
/// `stored_at` gives, for resting contacts stored in another, the index of each contact of their
/// own order (else empty).
void solve_speculative(StepContext& c, std::span<const std::uint32_t> stored_at,
                       SpeculativeScratch& scratch);

}  // namespace gp
