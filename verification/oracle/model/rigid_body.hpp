#pragma once
// The oracle's own rigid bodies: what it integrates, built from a scene without engine code
// (issue 14: the reference must not share the engine's mass properties, forces or geometry).

#include <optional>
#include <string>
#include <vector>

#include "gamephysics/models/types.hpp"
#include "scene/body.hpp"

namespace gp::oracle {

/// The state of a body: centre of mass and orientation, and their rates.
struct Motion {
  Vec2 position;            ///< m, world: the centre of mass
  double angle;             ///< ϕ [rad]
  Vec2 velocity;            ///< m/s: of the centre of mass
  double angular_velocity;  ///< ω [rad/s]
};

/// Where a body is: its centre of mass and its orientation.
struct Pose {
  Vec2 position;  ///< m, world: the centre of mass
  double angle;   ///< ϕ [rad]
};

/// Where a body in motion `m` is.
inline Pose pose_of(const Motion& m) {
  return {m.position, m.angle};
}

/// A shape as the oracle sees it: the convex hull of 1..8 vertices in its body's centre-of-mass
/// frame (same orientation as the body frame), swept by a disc of radius `radius`: disc = 1 vertex,
/// capsule or bare segment = 2 vertices, polygon = 3..8 vertices counter-clockwise with radius 0.
struct Hull {
  std::vector<Vec2> vertices;  ///< m, centre-of-mass frame
  double radius;               ///< m, ≥ 0
  double restitution;          ///< C_R [1]
  double friction;             ///< μ [1]
};

struct RigidBody {
  std::string name;
  BodyType type;
  double mass;            ///< kg (0 for a static or kinematic body without area)
  double moment;          ///< kg·m² about the centre of mass (0: the body does not rotate)
  double inverse_mass;    ///< 1/kg; 0 for static and kinematic bodies
  double inverse_moment;  ///< 1/(kg·m²); 0 for static, kinematic and non-rotating bodies
  Motion initial;         ///< at t = 0
  Vec2 force;             ///< N, constant (dynamic bodies)
  double torque;          ///< N·m, constant (dynamic bodies)
  std::optional<Vec2> force_arm;  ///< m, centre-of-mass frame: where `force` acts, if not the CoM
  std::vector<Hull> hulls;
};

struct World {
  std::vector<RigidBody> bodies;  ///< in the scene's order
  Vec2 gravity;                   ///< g [m/s²], uniform
  std::optional<double> G;        ///< m³/(kg·s²): pairwise gravitation between dynamic bodies
};

}  // namespace gp::oracle
