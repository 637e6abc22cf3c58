#pragma once
// What a step's contacts hand to the next step: per point, the impulses the solver accumulated,
// from which the same point of the next step starts (warm starting). The next step reads nothing
// else of a contact, and a whole contact point is several times larger.

#include <cstdint>
#include <vector>

#include "engine/collision/broadphase.hpp"
#include "engine/collision/manifold.hpp"
#include "engine/solver/contact_set.hpp"

namespace gp {

/// The accumulated impulses of one contact point, found again by its contact's pair of shapes
/// and its pair of features.
struct WarmStart {
  /// Shape indices fit in this many bits (BodyShapes holds no more shapes), so that the pair and
  /// the features share one key: 24 bytes a point, where the three apart take 32.
  static constexpr int kShapeBits = 24;

  /// The key of the pair of shapes (first, second) alone, ordered as the pairs are.
  static std::uint64_t pair_key(const ShapePair& pair) {
    return (std::uint64_t{pair.first} << kShapeBits) | pair.second;
  }

  /// The pair of shapes whose pair_key is `pair`.
  static ShapePair pair_of(std::uint64_t pair) {
    return {static_cast<std::uint32_t>(pair >> kShapeBits),
            static_cast<std::uint32_t>(pair & ((std::uint64_t{1} << kShapeBits) - 1))};
  }

  /// The key of a point: its pair's key (pair_key), then its features' (FeatureId::key).
  static std::uint64_t point_key(std::uint64_t pair, std::uint16_t features) {
    return pair << 16 | features;
  }

  /// point_key of the point: ordered as the contacts, by pair.
  std::uint64_t key;
  double normal;   ///< N·s
  double tangent;  ///< N·s

  std::uint64_t pair() const { return key >> 16; }
  std::uint16_t features() const { return static_cast<std::uint16_t>(key); }
};

/// Replaces `kept` by the impulses of the points of `contacts`, in the same order.
void keep_impulses(const ContactSet& contacts, std::vector<WarmStart>& kept);

}  // namespace gp
