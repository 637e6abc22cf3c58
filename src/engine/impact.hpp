#pragma once
// What the space reports of a collision it resolved at its time of impact.

#include "engine/core.hpp"

namespace gp {

/// A collision resolved at its time of impact t_c (IM:col2D).
struct Impact {
  double time;  ///< t_c [s]
  BodyId body_a;
  BodyId body_b;
  Vec2 normal;     ///< unit, from B towards A
  Vec2 point;      ///< m, world (the mean of the contact points)
  double impulse;  ///< j [N·s], the sum over the contact points
};

/// A point where two bodies touched at the end of the last step, with what the contact solver
/// pushed there.
struct ContactPointReport {
  BodyId body_a;
  BodyId body_b;
  Vec2 point;              ///< m, world: where the point was found, carried along with A since
  Vec2 normal;             ///< unit, from B towards A
  double normal_impulse;   ///< N·s, on A along the normal over the last sub-step (≥ 0)
  double tangent_impulse;  ///< N·s, along the normal turned a quarter turn counter-clockwise
};

}  // namespace gp
