#pragma once
// The mechanical quantities of a space that a reader checks a run by: the energies and momenta of
// each body and their sums, computed with the SRS's model functions (DD:kEnergy, DD:potEnergy)
// so that the conservation checks and the viewer show the same numbers.

#include "engine/space.hpp"

namespace gp::verification {

/// One dynamic body's share, at the space's current state.
struct BodyQuantities {
  double translational_energy = 0.0;  ///< J: DD:kEnergy with ω = 0, m ‖v‖² / 2
  double rotational_energy = 0.0;     ///< J: DD:kEnergy's rotational term, I ω² / 2
  double potential_energy = 0.0;      ///< J: DD:potEnergy in the uniform field, −m g · p
  Vec2 momentum = Vec2::Zero();       ///< kg·m/s: m v
  double angular_momentum = 0.0;      ///< kg·m²/s about the origin: m p × v + I ω
};

/// The sums over the dynamic bodies, with the pairwise gravitational potential.
struct Invariants {
  double translational_energy = 0.0;  ///< J
  double rotational_energy = 0.0;     ///< J
  /// J: the uniform field's, plus −G m_i m_j / d for each pair under pairwise gravitation.
  double potential_energy = 0.0;
  Vec2 momentum = Vec2::Zero();   ///< kg·m/s
  double angular_momentum = 0.0;  ///< kg·m²/s about the origin

  /// J: kinetic (translational and rotational) plus potential.
  double energy() const { return translational_energy + rotational_energy + potential_energy; }
};

/// The quantities of dynamic `body`; zero for static and kinematic bodies, whose infinite mass
/// carries no meaningful energy or momentum.
BodyQuantities body_quantities(const Space& space, BodyId body);

/// The sums over every dynamic body of `space`.
Invariants invariants(const Space& space);

}  // namespace gp::verification
