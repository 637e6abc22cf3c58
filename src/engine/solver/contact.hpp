#pragma once
// A contact constraint between two shapes, as the solver keeps it from one step to the next.

#include <cstdint>
#include <span>

#include "engine/collision/manifold.hpp"
#include "engine/collision/shape_pair.hpp"
#include "engine/core.hpp"
#include "gamephysics/models/dd/torque.hpp"

namespace gp {

/// The key of the contact a pair of shapes makes (Contact::key).
inline std::uint64_t contact_key(const ShapePair& pair) {
  return (std::uint64_t{pair.first} << 32) | pair.second;
}

/// The unit tangent of a contact whose normal is `normal`: the normal turned a quarter turn
/// counter-clockwise.
inline Vec2 contact_tangent(const Vec2& normal) {
  return {-normal.y(), normal.x()};
}

/// The normal velocity [m/s] the solver drives a point of overlap `depth` [m] to at least over a
/// step of h [s]: 0 where it touches or overlaps, and where it is apart by at most `touching_gap`
/// [m]; else the (negative) speed that closes its gap over the step.
inline double closing_target(double depth, double h, double touching_gap) {
  return depth < -touching_gap ? depth / h : 0.0;
}

/// How a shape's deepest point inside the other moves with its body, which the position passes
/// follow (correct_positions).
enum class AnchorKind : std::uint8_t {
  kFixed,        ///< fixed in the body: a polygon's or a segment's
  kCentredDisc,  ///< of a disc about its body's centre of mass: the radius along the normal, always
  kOffsetDisc,   ///< of a disc off it: the radius along the normal from a centre fixed in the body
};

/// One point of a contact constraint. The fields a solver pass reads come first, so that they
/// share two cache lines. The arms themselves are not kept: set_arms keeps their cross products
/// with the normal and the tangent, from which arm_a and arm_b rebuild them; nor are the points
/// fixed in each body that the position passes follow, which they rebuild from the arms.
struct ContactPointState {
  double normal_impulse = 0.0;          ///< N·s, accumulated over the step (≥ 0)
  double tangent_impulse = 0.0;         ///< N·s, accumulated over the step (|·| ≤ μ · normal)
  double target_normal_velocity = 0.0;  ///< m/s, what the solver drives v_rel·n to at least
  double normal_mass = 0.0;   ///< kg: impulse per unit change of v_rel·n (GD:impulse, C_R = 0)
  double tangent_mass = 0.0;  ///< kg: the same along the tangent
  /// m: the arms, from each body's centre of mass to the point, crossed with the normal and the
  /// tangent. Each is both the torque of a unit impulse along that direction (DD:torque) and the
  /// speed along it that a unit angular velocity gives the point, (ω × r)·d = ω (r × d)
  /// (DD:chaslesThm).
  double normal_arm_a = 0.0, normal_arm_b = 0.0;
  double tangent_arm_a = 0.0, tangent_arm_b = 0.0;
  /// m, overlap at detection (negative: still apart). A float, with the id in the room a double
  /// would leave: overlaps are within the contact margin or a few centimetres, where its 24 bits
  /// resolve nanometres, and a point takes 80 bytes rather than 88. (A point's bounce is kept
  /// beside it: ContactSet::bounce_velocities.)
  float depth = 0.0F;
  FeatureId id;
  AnchorKind anchor_a = AnchorKind::kFixed;  ///< in the room left after the id
  AnchorKind anchor_b = AnchorKind::kFixed;
};

/// Whether one of the points of `m` overlaps or is apart by at most `slop` [m], at the precision
/// a contact point keeps its depth (ContactPointState::depth): its contact holds the shapes
/// together, where one whose points are all farther apart closes a gap. Read from the manifold
/// rather than from the contact just written, whose stores a read back would wait on.
inline bool touches(const ContactManifold& m, double slop) {
  for (int k = 0; k < m.count; ++k) {
    if (static_cast<float>(m.points[k].depth) > -slop) return true;
  }
  return false;
}

/// Sets the arms of `p` [m], from A's and B's centre of mass to the point, for a contact whose
/// normal is `normal`.
inline void set_arms(ContactPointState& p, const Vec2& normal, const Vec2& arm_a,
                     const Vec2& arm_b) {
  const Vec2 tangent = contact_tangent(normal);
  p.normal_arm_a = dd::torque(arm_a, normal);
  p.normal_arm_b = dd::torque(arm_b, normal);
  p.tangent_arm_a = dd::torque(arm_a, tangent);
  p.tangent_arm_b = dd::torque(arm_b, tangent);
}

/// An arm [m] from its cross products with the unit normal n and tangent t: r × t = r · n and
/// r × n = −r · t, so r = (r × t) n − (r × n) t.
inline Vec2 arm_from(const Vec2& normal, double normal_arm, double tangent_arm) {
  return tangent_arm * normal - normal_arm * contact_tangent(normal);
}

/// The effective-mass matrix K of a two-point contact's normal constraints [1/kg]: entry (i, j)
/// is the change of v_rel·n at point i per unit normal impulse at point j, the diagonal being
/// GD:impulse's denominators; and its inverse [kg].
struct NormalBlock {
  double k11 = 0.0, k12 = 0.0, k22 = 0.0;
  /// All 0 when the block is not solvable; inverse11 = k22 / det(K) is then above 0, as k22 > 0,
  /// det(K) > 0 and k22 / det(K) ≥ 1 / k11: a flag of its own would take 8 bytes more a block.
  double inverse11 = 0.0, inverse12 = 0.0, inverse22 = 0.0;

  /// False when the two points are nearly redundant (ill-conditioned K): the solver then takes
  /// them one by one.
  bool solvable() const { return inverse11 > 0.0; }
};

/// A contact constraint between two shapes; its points and, for two points, its block are kept
/// by the ContactSet it belongs to. Its restitution is not kept: contact_restitution gives it.
struct Contact {
  /// The `block` of a contact of one point, which has none.
  static constexpr std::uint32_t kNoBlock = ~std::uint32_t{0};

  std::uint32_t shape_a;
  std::uint32_t shape_b;
  BodyId body_a;
  BodyId body_b;
  Vec2 normal;                ///< unit, world, from B towards A
  double friction;            ///< μ = √(μ_a μ_b)
  std::uint32_t first_point;  ///< where the points start in the ContactSet
  /// Of a two-point contact, where its NormalBlock is in the ContactSet; kNoBlock for one point.
  std::uint32_t block;

  /// Of points: 1 or 2.
  int count() const { return block == kNoBlock ? 1 : 2; }
  /// Orders contacts, and so matches them from step to step, by their pair of shapes.
  std::uint64_t key() const { return contact_key({shape_a, shape_b}); }
};

/// The arm [m] from A's centre of mass to point `p` of `c`.
inline Vec2 arm_a(const Contact& c, const ContactPointState& p) {
  return arm_from(c.normal, p.normal_arm_a, p.tangent_arm_a);
}
/// The arm [m] from B's centre of mass to point `p` of `c`.
inline Vec2 arm_b(const Contact& c, const ContactPointState& p) {
  return arm_from(c.normal, p.normal_arm_b, p.tangent_arm_b);
}

}  // namespace gp
