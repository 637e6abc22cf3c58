#pragma once
// A body's mass, centre of mass and moment of inertia from its shapes (DD:ctrOfMass,
// DD:momentOfInertia with the parallel-axis theorem), or from the values the scene gives.

#include "gamephysics/models/types.hpp"
#include "scene/body.hpp"

namespace gp::oracle {

struct BodyMass {
  double mass;    ///< kg; 0 for a body with neither area nor a given mass
  double moment;  ///< kg·m² about the centre of mass; 0 for a body that does not rotate
  Vec2 center;    ///< m, body frame: the centre of mass
};

/// The rules of docs/scene-format.md: each shape weighs ρ·area at its centroid (a bare segment
/// has no area and weighs nothing); a given `mass` scales every density alike, keeping the centre
/// and scaling the moment; a given `moment` replaces the computed one. A body without area (no
/// shapes, or bare segments only) is a point mass at its body origin, with the given moment or 0.
BodyMass body_mass(const BodyDef& body);

}  // namespace gp::oracle
