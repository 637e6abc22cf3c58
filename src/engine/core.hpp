#pragma once
// The engine's core types, shared by every stage: a body's id, its inertia as collisions see it,
// the state the integrators advance and a force callback's result. Structure of arrays indexed by
// body id: one contiguous array per quantity keeps the hot loops over bodies cache-friendly.

#include <cstdint>
#include <vector>

#include "gamephysics/models/types.hpp"
#include "scene/body_state.hpp"

namespace gp {

/// A body's index in its space, counted from 0 in the order of adding.
using BodyId = std::uint32_t;

/// A force and a torque about the centre of mass.
struct Wrench {
  Vec2 force = Vec2::Zero();  ///< N
  double torque = 0.0;        ///< N·m
};

/// Inverse masses [1/kg] and moments [1/(kg·m²)] by body id; 0 for bodies collisions cannot
/// move or turn.
struct BodyInertia {
  std::vector<double> inverse_mass;
  std::vector<double> inverse_moment;
};

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
