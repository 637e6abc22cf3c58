#pragma once
// The state the integrators advance, as structure of arrays indexed by body id: one contiguous
// array per quantity keeps the hot loops over bodies cache-friendly.

#include <vector>

#include "engine/body_state.hpp"
#include "gamephysics/models/types.hpp"

namespace gp {

// Eigen vectors are not initialised on construction: every resize fills with zeros so that the
// entries of bodies a stage does not write (static, kinematic) are defined.
struct MotionState {
  std::vector<Vec2> position;            ///< m, centre of mass
  std::vector<double> angle;             ///< rad, in [0, 2π)
  std::vector<Vec2> velocity;            ///< m/s
  std::vector<double> angular_velocity;  ///< rad/s

  /// The state of body `b`, read or written whole.
  BodyState of(std::size_t b) const {
    return {position[b], angle[b], velocity[b], angular_velocity[b]};
  }
  void set(std::size_t b, const BodyState& state) {
    position[b] = state.position;
    angle[b] = state.angle;
    velocity[b] = state.velocity;
    angular_velocity[b] = state.angular_velocity;
  }

  void resize(std::size_t n) {
    position.resize(n, Vec2::Zero());
    angle.resize(n);
    velocity.resize(n, Vec2::Zero());
    angular_velocity.resize(n);
  }
};

/// Accelerations of every body, indexed by body id.
struct Accelerations {
  std::vector<Vec2> linear;     ///< m/s²
  std::vector<double> angular;  ///< rad/s²

  void resize(std::size_t n) {
    linear.resize(n, Vec2::Zero());
    angular.resize(n);
  }
};

}  // namespace gp
