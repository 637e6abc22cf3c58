#pragma once
// What a user gives to create a body (FR:Input-Initial-Conditions, FR:Input-Surface-Properties).

#include <optional>
#include <string>
#include <vector>

#include "gamephysics/models/types.hpp"
#include "scene/shape.hpp"

namespace gp {

/// Dynamic bodies move under forces and collisions; static bodies never move; kinematic bodies
/// move at their given velocity and are not moved by forces or collisions.
enum class BodyType { Dynamic, Static, Kinematic };

/// A shape of a body with its surface properties. Contacts combine two shapes' properties as
/// C_R = max(C_R,a, C_R,b) (the bouncier surface wins, as in Box2D) and μ = √(μ_a μ_b).
struct ShapeDef {
  Shape shape;
  double restitution = 0.0;  ///< C_R [1], 0 ≤ C_R ≤ 1 (SRS data constraint)
  double friction = 0.0;     ///< μ [1], ≥ 0; 0 is the SRS's frictionless default
  double density = 1.0;      ///< ρ [kg/m²], > 0: mass per unit area (2D)
};

/// A body as the user describes it. Shape coordinates are in the body frame, whose origin is at
/// `position` and turned by `angle`; the engine computes the centre of mass from the shapes.
struct BodyDef {
  std::string name;
  BodyType type = BodyType::Dynamic;
  Vec2 position = Vec2::Zero();     ///< m: origin of the body frame, world
  double angle = 0.0;               ///< ϕ [rad]
  Vec2 velocity = Vec2::Zero();     ///< m/s: of the centre of mass
  double angular_velocity = 0.0;    ///< ω [rad/s]
  std::optional<double> mass;       ///< kg, > 0: overrides the shapes' densities
  std::optional<double> moment;     ///< I [kg·m²] about the centre of mass, > 0: overrides
  Vec2 force = Vec2::Zero();        ///< N: constant applied force
  std::optional<Vec2> force_point;  ///< m, body frame: where `force` acts (default: the CoM)
  double torque = 0.0;              ///< N·m: constant applied torque
  std::vector<ShapeDef> shapes;     ///< none: a point mass (give mass, and moment to rotate)
};

}  // namespace gp
