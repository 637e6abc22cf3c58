#pragma once
// One time step of Moreau–Jean's scheme for the measure differential inclusion of rigid bodies
// with unilateral contact, Newton's impact law and Coulomb friction (Moreau 1988, Jean 1999;
// Acary and Brogliato 2008, §10.1), θ = ½:
//   M (v⁺ − v⁻) = h f(q⁻) + Jᵀ P,     q⁺ = q⁻ + h (v⁻ + v⁺) / 2,
// with, at every contact of the index set (index_set.hpp), the impulse P over the step by
//   ġ⁺ + e min(ġ⁻, 0) ≥ 0 ⊥ P_n ≥ 0   and Coulomb's law on (P_n, P_t) with the slip ṡ⁺,
// the LCP the oracle's impacts solve (impacts.hpp), by its own Lemke's method. Smooth forces and
// impacts are one law at the velocity level, so a pile costs one LCP a step however many
// contacts open and close in it; the price is first order in h.

#include <span>

#include "verification/oracle/stepping/index_set.hpp"

namespace gp::oracle {

/// Advances `motions` (every body of `world`) by `h` [s] under the applied forces and the
/// impulses at `contacts` (the index set at `motions`). The LCP is solved per cluster of bodies
/// that the contacts join (static and kinematic bodies join nothing), so that bodies apart cost
/// one small problem each. Kinematic bodies move at their velocities, static bodies stay.
void moreau_jean_step(const World& world, std::span<const StepContact> contacts, double h,
                      std::span<Motion> motions);

}  // namespace gp::oracle
