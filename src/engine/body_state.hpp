#pragma once
// What the engine reports of a body, and what a force callback gives back.

#include "gamephysics/models/types.hpp"
#include "scene/body_state.hpp"

namespace gp {

/// A force and a torque about the centre of mass.
struct Wrench {
  Vec2 force = Vec2::Zero();  ///< N
  double torque = 0.0;        ///< N·m
};

}  // namespace gp
