#pragma once
#include <cmath>
#include <numbers>

#include "gamephysics/models/registry.hpp"
#include "gamephysics/models/types.hpp"

namespace gp::dd {

/// DD:angDisp — angular displacement θ = ϕ(t) − ϕ(t₀), solved for the new orientation.
/// (The SRS writes θ = dϕ/dt, which is a rate: srs/errata.md E-DD-ANGDISP.) The result is reduced
/// to the SRS output range, taken half-open as 0 ≤ ϕ < 2π so that each orientation has one value.
///   ϕ(t) = ϕ(t₀) + θ  (mod 2π)
/// @param orientation           ϕ(t₀) [rad]
/// @param angular_displacement  θ over [t₀, t] [rad]
/// @return ϕ(t) in [0, 2π) [rad]
template <class Angle = double>
inline Angle rotated_orientation(models::In<Angle> orientation,
                                 models::In<Angle> angular_displacement) {
  constexpr double two_pi = 2.0 * std::numbers::pi;
  Angle phi = orientation + angular_displacement;
  if (phi >= 0.0 && phi < two_pi) return phi;  // the common case, without a division
  // Within a turn of the range (a body at rest near ϕ = 0 turns across it at every step) fmod is
  // not needed: between 2π and 4π, ϕ − 2π is its result, exact (Sterbenz); below 0, it would
  // leave ϕ as it is.
  if (phi >= two_pi && phi < 2.0 * two_pi) {
    phi -= two_pi;
  } else if (phi <= -two_pi || phi >= two_pi) {
    phi = std::fmod(phi, two_pi);
  }
  if (phi < 0.0) phi += two_pi;
  // fmod of a tiny negative number plus 2π rounds to 2π itself, which is outside the range.
  return phi >= two_pi ? models::zero<Angle>() : phi;
}

GP_REGISTER_MODEL("DD:angDisp", dd, rotated_orientation);

}  // namespace gp::dd
