#pragma once
// A body's state as a trajectory reports it, whoever computed it: the engine or the oracle.

#include "gamephysics/models/types.hpp"

namespace gp {

/// A body's state: centre of mass, orientation in [0, 2π) (SRS output constraint), velocities.
struct BodyState {
  Vec2 position;
  double angle;
  Vec2 velocity;
  double angular_velocity;
};

}  // namespace gp
