#pragma once
// The stability metrics of the hard cases of other solvers, read from the bodies' states alone,
// so that ours and the peers are measured by one ruler: how far the bodies drift from where they
// were set, how deep they overlap, how fast they move and what kinetic energy they gain.

#include <vector>

#include "verification/peers/peer_scene.hpp"

namespace gp::verification {

/// m: the largest distance of a dynamic body's centre of mass in `now` from where it was in
/// `start` (states in BodyId order of `bodies`).
double largest_drift(const std::vector<peers::PeerBody>& bodies,
                     const std::vector<BodyState>& start, const std::vector<BodyState>& now);

/// m: the largest penetration depth over the pairs of bodies with at least one dynamic, each
/// placed at its state: the shortest translation that separates the two shapes (the separating
/// axis theorem on their vertices, rounded by their radii), 0 for shapes apart.
double largest_overlap(const std::vector<peers::PeerBody>& bodies,
                       const std::vector<BodyState>& states);

/// m/s: the largest speed of a dynamic body's centre of mass.
double largest_speed(const std::vector<peers::PeerBody>& bodies,
                     const std::vector<BodyState>& states);

/// J: the kinetic energy of the dynamic bodies, Σ ½ m |v|² + ½ I ω² (DD:kEnergy, with the
/// rotation term; m in kg, I in kg·m²).
double kinetic_energy(const std::vector<peers::PeerBody>& bodies,
                      const std::vector<BodyState>& states);

}  // namespace gp::verification
