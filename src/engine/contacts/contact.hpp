#pragma once
// A contact constraint between two shapes, as the solver keeps it from one step to the next.

#include <array>
#include <cstdint>

#include "engine/collision/broadphase.hpp"
#include "engine/collision/contact.hpp"
#include "engine/dynamics/force_model.hpp"

namespace gp {

/// The key of the contact a pair of shapes makes (Contact::key).
inline std::uint64_t key_of(const ProxyPair& pair) {
  return (std::uint64_t{pair.first} << 32) | pair.second;
}

/// One point of a contact constraint.
struct ContactPointState {
  FeatureId id;
  Vec2 arm_a = Vec2::Zero();  ///< m, from A's centre of mass to the point
  Vec2 arm_b = Vec2::Zero();  ///< m, from B's centre of mass to the point
  /// m, in A's frame: A's deepest point is this point plus anchor_radius_a along −normal (a
  /// circle's centre and radius, so that a disc's turning does not move its deepest point).
  Vec2 local_anchor_a = Vec2::Zero();
  /// m, in B's frame: B's deepest point is this point plus anchor_radius_b along +normal.
  Vec2 local_anchor_b = Vec2::Zero();
  double anchor_radius_a = 0.0;         ///< m
  double anchor_radius_b = 0.0;         ///< m
  double depth = 0.0;                   ///< m, overlap at detection (negative: still apart)
  double normal_impulse = 0.0;          ///< N·s, accumulated over the step (≥ 0)
  double tangent_impulse = 0.0;         ///< N·s, accumulated over the step (|·| ≤ μ · normal)
  double target_normal_velocity = 0.0;  ///< m/s, what the solver drives v_rel·n to at least
  /// m/s: v_rel·n before the step when the point was touching and approaching faster than the
  /// restitution threshold (it then bounces with C_R), else 0.
  double approach_velocity = 0.0;
  double normal_mass = 0.0;   ///< kg: impulse per unit change of v_rel·n (GD:impulse, C_R = 0)
  double tangent_mass = 0.0;  ///< kg: the same along the tangent
};

struct Contact {
  std::uint32_t shape_a;
  std::uint32_t shape_b;
  BodyId body_a;
  BodyId body_b;
  Vec2 normal;  ///< unit, world, from B towards A
  int count;
  std::array<ContactPointState, 2> points;
  double restitution;  ///< C_R = max of the two shapes'
  double friction;     ///< μ = √(μ_a μ_b)
  /// 1/kg: change of v_rel·n at one point per unit normal impulse at the other (two points only);
  /// the diagonal terms are 1 / normal_mass.
  double coupling = 0.0;

  /// Orders contacts, and so matches them from step to step, by their pair of shapes.
  std::uint64_t key() const { return key_of({shape_a, shape_b}); }
};

}  // namespace gp
