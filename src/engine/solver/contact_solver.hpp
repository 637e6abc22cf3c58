#pragma once
// The contact solver's stages over a sub-step, on the step context: effective masses and warm
// start, the direct solve of islands, the sequential-impulse passes, the bounce, the
// displacement of the impulses, the impacts handed over as speculative contacts, and the position
// passes. It owns their scratch, so that a warmed-up step allocates nothing (but in the sparse
// solve of an uneven island over 64 points), and the order of the contacts' passes
// (ContactBatches), which run on the threads of the current task arena.

#include <limits>

#include "engine/solver/contact_batches.hpp"
#include "engine/solver/island_solver.hpp"
#include "engine/solver/position_passes.hpp"
#include "engine/solver/speculative.hpp"

namespace gp {

struct StepContext;

class ContactSolver {
 public:
  /// The contacts' order of solving (ContactBatches), the contacts stored in it where that
  /// pays (ContactBatches::store_in_order); each point's effective masses, target and bounce
  /// (prepare_contacts, from the start state), then the impulses carried over from the last
  /// sub-step applied to the velocities.
  void prepare(StepContext& c);
  /// The islands of at most Settings::direct_solve_points points, or of at most
  /// direct_solve_uneven_points of uneven masses, solved at once.
  void solve_small_islands(StepContext& c);
  /// Sequential impulses until a pass changes no velocity by more than the tolerance.
  void solve_velocities(StepContext& c);
  /// The bounce of the points that were approaching, in one pass after the others.
  void apply_restitution(StepContext& c);
  /// The bodies moved by the impulses' velocity changes over the sub-step.
  void move_by_impulses(StepContext& c);
  /// The impacts handed over as speculative contacts, solved with the resting contacts near
  /// them and their overlap corrected; they last this step only.
  void solve_speculative(StepContext& c);
  /// The position passes over the resting contacts.
  void correct_positions(StepContext& c);
  /// The contacts back in their own order (by pair of shapes), where prepare stored them in the
  /// order of solving: the warm starts are kept, and the next step's contacts matched, in it.
  void restore_order(StepContext& c);

 private:
  ContactBatches batches_;  ///< of the sub-step's contacts, found in prepare
  DirectSolveScratch islands_;
  SpeculativeScratch speculative_;
  PositionCorrection positions_;
  /// m: the deepest overlap of the contacts prepare found, until correct_positions reads it.
  double deepest_ = std::numeric_limits<double>::infinity();
  /// Taken in prepare, for move_by_impulses; its room then serves the position passes.
  BodyVelocities before_impulses_;
};

}  // namespace gp
