#pragma once
// Time of impact without sub-stepping the whole space (FR:Determine-Collision-Response-Over-Time,
// IM:col2D). When the accelerations are constant over a step, a body's ballistic path is exact,
// so an impact at t_c inside the step can be resolved for its two bodies alone: their states at
// t_c come from the path, IM:col2D changes their velocities there, and the rest of their path is
// the ballistic path from the new state. Every other body takes the step in one piece. An impact
// on a body that also has resting contacts is left to the contact solver as a speculative
// contact instead, as a heap's many small impacts are; only isolated impacts (free flight into a
// wall, the floor or another free body) take the exact path.

#include <optional>
#include <span>
#include <vector>

#include "engine/collision/body_shapes.hpp"
#include "engine/core.hpp"
#include "engine/impacts/impacts.hpp"
#include "engine/solver/contact_set.hpp"
#include "scene/settings.hpp"

namespace gp {

struct StepContext;

class LocalImpacts {
 public:
  /// Finds the impacts of the sub-step: the candidate pairs that are apart at its start and touch
  /// within it along the context's motion (only while impacts are still allowed this step), an
  /// impact's time only bracketed where it can be (Touch). Their speculative contacts leave the
  /// context's contacts (both sorted by pair), as the impacts take their place.
  void classify(StepContext& ctx);

  /// Pending impacts on bodies that take part in the contacts become speculative contacts (made
  /// at the start placement and state; see solve_speculative), and so do impacts on bodies
  /// thereby added, until no pending impact touches a body of the contact solver; a body takes
  /// part when one of its contacts is engaged over the sub-step. The other contacts of bodies
  /// left with impacts are dropped: the impacts' own search covers them.
  void hand_over(StepContext& ctx);

  /// After hand_over(), resolves the remaining impacts in time order, each at its t_c = t + τ,
  /// and logs them in the context's impacts (counted against Settings::max_impacts_per_step).
  /// Each body an impact changes gets, in the start state, the state from which its ballistic
  /// path over the step passes through its state just after the impact; its shapes' placements
  /// follow: in world_start where the rest of the path starts (at the impact), in end_bounds
  /// where it ends. The other contacts of the changed bodies (none of them engaged, since a changed
  /// body is not the solver's) are dropped, as hand_over() drops those of the bodies with
  /// impacts: they were made from the bodies' old paths. The search after each impact finds the
  /// changed bodies' impacts with the bodies outside the solver; with a body of the solver it
  /// only makes sure that neither can pass through the other within the step, and the next
  /// step's contact takes over. Returns false, leaving the step to be sub-stepped, when a changed
  /// path could carry a body through one of the solver's bodies within the step, or when impacts
  /// are left at the limit (the sub-steps then resolve the rest of the step's contacts at its
  /// end, as the limit promises, rather than leave those bodies with neither impact nor contact).
  bool resolve(StepContext& ctx);

 private:
  struct Pending {
    ShapePair pair;
    /// Its time τ [s] from the start of the step, searched for by resolve() where classify()
    /// only bracketed it.
    Touch touch;
  };

  /// Whether contact `c` (of the context's contacts) can push during the sub-step from its start
  /// state: a point touching, or closing its gap within the sub-step.
  bool engaged(const StepContext& ctx, const Contact& c) const;
  bool in_solver(const StepContext& ctx, std::uint32_t shape) const;
  /// Makes body b the solver's, if it is dynamic.
  void join(const StepContext& ctx, BodyId b);
  /// Joins the bodies of each contact that `asked(contact)` picks and that is engaged.
  template <typename Asked>
  void join_engaged(const StepContext& ctx, const Asked& asked);
  bool changed(const ShapeRecord& shape) const {
    return roles_[shape.body] == BodyRole::kResolving;
  }
  /// Drops from the context's contacts every contact of a dynamic body whose role is kWithImpact.
  void drop_contacts_with_impacts(StepContext& ctx) const;
  /// Moves body b in `start` along its ballistic path from there by τ [s] (back for τ < 0).
  void follow_path(BodyId b, double tau, StepContext& ctx) const;
  /// Finds the impacts from τ on of the shapes of the changed bodies (changed_), whose paths
  /// have changed, having placed them at τ in world_start and at h in end_bounds; false when one
  /// of them could pass through a body of the contact solver.
  bool search_after(StepContext& ctx, double tau);

  std::vector<Pending> pending_;
  // classify's block of pairs apart (indices into the context's pairs) and their touches, on
  // several threads.
  std::vector<std::uint32_t> apart_;
  std::vector<std::optional<Touch>> touches_;
  // Who owns a body's contacts this step, one role per body. A body's contacts follow it: those
  // of a body in the solver are the contact solver's (resting, or impacts handed over as
  // speculative contacts); those of a body with an impact are dropped, as its impacts' search
  // covers them. Transitions: hand_over() makes a dynamic body with an engaged contact kInSolver
  // and the bodies of the impacts left kWithImpact; resolve() makes the dynamic bodies of the
  // impact at hand kResolving, and kWithImpact once it is resolved. kInSolver is final. Only the
  // bodies of impacts are asked at first (kInImpact until then); resolve() asks the rest.
  enum class BodyRole : std::uint8_t {
    kFree,        // in no impact and no engaged contact, or not yet asked
    kInImpact,    // dynamic, in a pending impact, not yet found in an engaged contact
    kInSolver,    // dynamic, with a contact engaged over the step: the contact solver's
    kWithImpact,  // in a pending impact, or changed by a resolved one: the exact path's
    kResolving,   // dynamic, in the impact being resolved
  };
  std::vector<BodyRole> roles_;
  // Scratch kept between steps so that impacts allocate nothing once the scene is warmed up.
  std::vector<ShapePair> group_;
  std::vector<BodyId> changed_;
  ContactSet impact_contacts_;
  // The static and kinematic bodies of an impact, held aside while the impact is resolved in the
  // step's start state.
  struct Held {
    BodyId body;
    BodyState state;
  };
  std::vector<Held> held_;
};

}  // namespace gp
