#pragma once
// Mass, centre of mass and moment of inertia of a body from its shapes and their densities
// (DD:ctrOfMass, DD:momentOfInertia and the parallel-axis theorem), or from given values.

#include "scene/body.hpp"

namespace gp {

struct MassSetup {
  double mass;        ///< kg; 0 for a body that has neither area nor a given mass
  double moment;      ///< kg·m² about the centre of mass; 0 if the body cannot rotate
  Vec2 local_center;  ///< m, body frame: the centre of mass
};

/// Each shape weighs ρ·area at its centroid. A given mass scales all densities alike (keeping the
/// centre of mass); a given moment replaces the computed one. A body with no area and no given
/// moment has moment 0 (it does not rotate), and its centre is the body origin.
MassSetup mass_setup(const BodyDef& def);

}  // namespace gp
