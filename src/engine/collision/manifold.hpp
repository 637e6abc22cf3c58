#pragma once
// The result of a narrowphase test: where two shapes touch, along which normal, and how deep
// (FR:Determine-Collisions). Input to the impulse model (GD:impulse).

#include <array>
#include <cstdint>

#include "gamephysics/models/types.hpp"

namespace gp {

/// The pair of features, one per shape, that a contact point comes from: vertex indices of a
/// polygon (or 0, 1 for a segment's ends a, b; 0 for a circle). The same pair of features gives
/// the same id frame after frame, so a solver can carry a point's impulse over (warm starting).
struct FeatureId {
  std::uint8_t feature_a = 0;
  std::uint8_t feature_b = 0;

  /// One number per id, for hashing and matching.
  std::uint16_t key() const { return static_cast<std::uint16_t>((feature_a << 8) | feature_b); }
  bool operator==(const FeatureId&) const = default;
};

/// One point of contact.
struct ContactPoint {
  /// m, world: midway between the two surfaces, so the same whichever shape is called A.
  Vec2 position = Vec2::Zero();
  /// m: how far the shapes overlap along the normal at this point; negative for a speculative
  /// point, whose shapes are still that far apart.
  double depth = 0.0;
  FeatureId id;
};

/// The contact between shape A and shape B: 0, 1 (vertex to edge, A:collisionType) or 2 (edge to
/// edge, LC:Expanded-Collisions) points sharing one normal.
struct ContactManifold {
  /// Unit, world, pointing from B towards A: the impulse j·n acts on A and −j·n on B. Meaningless
  /// when count is 0.
  Vec2 normal = Vec2::Zero();
  std::array<ContactPoint, 2> points{};
  int count = 0;
};

}  // namespace gp
