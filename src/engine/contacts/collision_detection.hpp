#pragma once
// FR:Determine-Collisions: which shapes are close (broadphase, sweep and prune on boxes swept over
// the step) and where they touch (narrowphase manifolds), as contact constraints carrying the
// impulses of the previous step for warm starting.

#include <vector>

#include "engine/collision/broadphase.hpp"
#include "engine/collision/pair_order.hpp"
#include "engine/contacts/body_shapes.hpp"
#include "engine/contacts/contact_set.hpp"
#include "engine/contacts/warm_start.hpp"

namespace gp {

/// Appends to `contacts` the contact constraint of the shapes of `pair`, whose manifold `m` was
/// found in state `s`: combined friction, and per point its depth and arms. Impulses start at 0.
Contact& append_contact(const ProxyPair& pair, const BodyShapes& shapes, const ContactManifold& m,
                        const MotionState& s, ContactSet& contacts);

class CollisionDetection {
 public:
  /// `margin` [m]: shapes this far apart already get (speculative) contact points.
  explicit CollisionDetection(double margin) : margin_(margin), broadphase_(margin) {}

  /// The pairs of shapes of different bodies, at least one of them dynamic, whose boxes overlap
  /// when each is grown to cover both its `start` and its `end` placement.
  const std::vector<ProxyPair>& candidate_pairs(const BodyShapes& shapes,
                                                const std::vector<char>& dynamic,
                                                const WorldShapes& start, const WorldShapes& end);

  /// The contacts of `pairs` at placement `world` of state `s`, sorted by key; a point whose pair
  /// and features were in `previous` (sorted by key) starts with its impulses times
  /// `impulse_scale`.
  void find_contacts(const std::vector<ProxyPair>& pairs, const BodyShapes& shapes,
                     const WorldShapes& world, const MotionState& s,
                     const std::vector<WarmStart>& previous, double impulse_scale,
                     ContactSet& contacts) const;

  double margin() const { return margin_; }

 private:
  double margin_;
  SweepAndPrune broadphase_;
  PairOrder pair_order_;
  std::vector<BodyId> body_of_;   // per shape
  std::vector<ProxyPair> pairs_;  // the broadphase's, filtered and sorted in place
};

}  // namespace gp
