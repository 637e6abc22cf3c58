#pragma once
// The oracle's world, built from a scene file's data alone.

#include "scene/scene.hpp"
#include "verification/oracle/model/rigid_body.hpp"

namespace gp::oracle {

/// The bodies of `scene` as the oracle integrates them: mass properties from body_mass, every
/// position at the centre of mass (as the trajectory CSV reports it), every shape as a Hull about
/// that centre. Static bodies start at rest; the initial angle is reduced to [0, 2π) (DD:angDisp),
/// as the engine reports it. `scene` must have passed the engine's checks (SRS data constraints).
World build_world(const Scene& scene);

/// `shape` as a Hull about `center` [m, body frame]: its vertices moved by −center, its radius
/// and surface properties as given.
Hull hull_of(const ShapeDef& shape, const Vec2& center);

}  // namespace gp::oracle
