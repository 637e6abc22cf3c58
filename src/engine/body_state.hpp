#pragma once
// What the engine reports of a body, and what a force callback gives back.

#include "gamephysics/models/types.hpp"

namespace gp {

/// A body's state: centre of mass, orientation in [0, 2π) (SRS output constraint), velocities.
struct BodyState {
  Vec2 position;
  double angle;
  Vec2 velocity;
  double angular_velocity;
};

/// A force and a torque about the centre of mass.
struct Wrench {
  Vec2 force = Vec2::Zero();  ///< N
  double torque = 0.0;        ///< N·m
};

}  // namespace gp
