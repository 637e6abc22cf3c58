#pragma once
// The events of the hybrid integration, as root functions of the state for SUNDIALS' root
// finder, each falling through zero when its event happens:
//   Approach   two hulls not in contact: their signed distance, plus 1e-12 m (contact onset), or
//              plus 1e-10 m for a pair released at rest (see release());
//   Landing    another vertex of a body resting on an edge: its gap to that edge's line;
//   LiftOff    an active contact: its normal force;
//   StickLimit a sticking contact: μ f_n ∓ f_t (friction reaches its bound: stick to slip);
//   SlipStop   a sliding contact: its slip, signed so that it falls, plus the slip floor (slip to
//              stick, or reversal);
//   OffEdge    a vertex on an edge: its distance to either end (it slides off the edge);
//   OffCorner  a contact at a corner: how far its normal is inside the corner's normal cone
//              (corner on corner: each corner's).
// The list is rebuilt whenever the active contacts change.

#include <cstddef>
#include <span>
#include <vector>

#include "verification/oracle/contact/active_contact.hpp"
#include "verification/oracle/hybrid/hybrid_system.hpp"

namespace gp::oracle {

enum class RootKind { Approach, Landing, LiftOff, StickLimit, SlipStop, OffEdge, OffCorner };

struct Root {
  RootKind kind;
  std::size_t index;  ///< the pair (Approach) or the active contact (every other kind)
  /// Landing: the vertex; StickLimit: which side (0, 1); OffEdge: which end (0: the start, 1:
  /// the end; 2, 3: the same, for a vertex armed at that end, watched once past it by the end
  /// tolerance); OffCorner: the second's corner's side (0, 1) or the first's (2, 3).
  int detail;
};

class EventWatch {
 public:
  /// Watches every pair of hulls of `world` on different bodies, one of them dynamic, except
  /// pairs of bare segments (no area: they never touch). A vertex within `end_tolerance` [m] of
  /// an end of its edge is watched leaving it only once that far past it; a slip reverses once
  /// it is `slip_floor` [m/s] the other way. `world` must outlive this.
  EventWatch(const World& world, double end_tolerance, double slip_floor);

  /// Marks pair `p` as let go at rest (lift-off with no speed): it parts as t² or t³, within
  /// the solver's error of its positions (1e-12 m) for a while, so its approach is an event only
  /// at 1e-10 m of overlap until it is 1e-10 m apart (or in contact) at an arming.
  void release(std::size_t p);

  const std::vector<HullPair>& pairs() const { return pairs_; }
  /// N: a contact force this small counts as zero; a lift-off is found at −force_floor().
  double force_floor() const { return force_floor_; }

  /// Rebuilds the root functions for the active `contacts`, with every body at `motions`.
  void arm(std::span<const ActiveContact> contacts, std::span<const Motion> motions);
  std::size_t size() const { return roots_.size(); }
  const Root& root(std::size_t i) const { return roots_[i]; }

  /// The root functions at `snapshot` (whose contacts are those armed) into g.
  void evaluate(const Snapshot& snapshot, std::span<const ActiveContact> contacts, double* g) const;

  /// How long [s] the solver may go from `snapshot` before it must stop and look again: no pair
  /// without contact can move into the other by more than its margin in that time, so that no
  /// step can jump over a whole pass-through, which the root finder would not see. Infinite when
  /// nothing moves.
  double horizon(const Snapshot& snapshot) const;

  /// The signed distance [m] of pair `p` at `motions`.
  double distance(std::size_t p, std::span<const Motion> motions) const;

 private:
  const World& world_;
  double end_tolerance_;
  double slip_floor_;
  double force_floor_;  // N: a force this small counts as zero (kForceShare)
  std::vector<HullPair> pairs_;
  std::vector<double> reach_;  // m: per pair, the farthest point of hull a, then of hull b
  std::vector<Root> roots_;
  std::vector<bool> in_contact_;  // per pair, as armed
  std::vector<bool> released_;    // per pair: let go at rest, not yet 1e-10 m apart
};

}  // namespace gp::oracle
