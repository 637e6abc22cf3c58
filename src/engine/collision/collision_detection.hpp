#pragma once
// FR:Determine-Collisions: which shapes are close (broadphase, sweep and prune on boxes swept over
// the step) and where they touch (narrowphase manifolds), as contact constraints carrying the
// impulses of the previous step for warm starting.

#include <cstdint>
#include <vector>

#include "engine/collision/body_shapes.hpp"
#include "engine/collision/candidate_pairs.hpp"
#include "engine/solver/contact_set.hpp"
#include "engine/solver/warm_start.hpp"

namespace gp {

struct StepContext;

/// Appends to `contacts` the contact constraint of the shapes of `pair`, whose manifold `m` was
/// found in state `s`: combined friction, and per point its depth and arms. Impulses start at 0.
Contact& append_contact(const ShapePair& pair, const BodyShapes& shapes, const ContactManifold& m,
                        const MotionState& s, ContactSet& contacts);

class CollisionDetection {
 public:
  /// Fewer candidate pairs are collided, and swept for impacts (LocalImpacts), on one thread even
  /// where there are more: a second one gains them little, the contacts it writes are then read on
  /// the first by the stages after, and a worker asleep takes about as long to wake (16-22 µs on
  /// these machines).
  static constexpr std::size_t kParallelPairs = 4096;

  /// `margin` [m]: shapes this far apart already get (speculative) contact points.
  explicit CollisionDetection(double margin) : margin_(margin), candidates_(margin) {}

  /// The pairs of shapes of different bodies, at least one of them dynamic, whose boxes overlap
  /// when each is grown to cover both its `start` and its `end` placement (CandidatePairs).
  const std::vector<ShapePair>& candidate_pairs(const BodyShapes& shapes,
                                                const std::vector<char>& dynamic,
                                                const WorldShapes& start, const WorldBounds& end) {
    return candidates_.find(shapes, dynamic, start, end);
  }

  /// Removes the pairs in `dropped` from the last candidate pairs, in place; returns those left.
  std::span<const ShapePair> drop_pairs(std::span<const ShapePair> dropped);

  /// The context's contacts: those of its candidate pairs at the start placement and state,
  /// sorted by key; a point whose pair and features were among the warm starts (sorted by key)
  /// starts with their impulses times the warm-start scale. Marks in the context's touching_pairs
  /// each pair whose contact touches.
  void find_contacts(StepContext& ctx);
  /// Frees the room of the candidate pairs (CandidatePairs::release) and of the manifolds, for a
  /// space that will find none for a while.
  void release();

  double margin() const { return margin_; }

 private:
  double margin_;
  CandidatePairs candidates_;
  std::vector<ContactManifold> manifolds_;  // per pair of a block of find_contacts
  // Per run of pairs of the block: the room its contacts take, then where they start.
  std::vector<ContactCursor> runs_;
};

}  // namespace gp
