#pragma once
// Time of impact without sub-stepping the whole space (FR:Determine-Collision-Response-Over-Time,
// IM:col2D). When the accelerations are constant over a step, a body's ballistic path is exact,
// so an impact at t_c inside the step can be resolved for its two bodies alone: their states at
// t_c come from the path, IM:col2D changes their velocities there, and the rest of their path is
// the ballistic path from the new state. Every other body takes the step in one piece. An impact
// on a body that also has resting contacts is left to the contact solver as a speculative
// contact instead, as a heap's many small impacts are; only isolated impacts (free flight into a
// wall, the floor or another free body) take the exact path.

#include <span>
#include <vector>

#include "engine/body_state.hpp"
#include "engine/contacts/body_shapes.hpp"
#include "engine/contacts/contact_set.hpp"
#include "engine/contacts/impacts.hpp"
#include "scene/settings.hpp"

namespace gp {

class LocalImpacts {
 public:
  LocalImpacts(const BodyShapes& shapes, const BodyInertia& inertia,
               const std::vector<char>& dynamic, const Settings& settings)
      : shapes_(shapes), inertia_(inertia), dynamic_(dynamic), settings_(settings) {}

  /// Finds the impacts of a step of h [s] from placement `start` to `end` along `motion`:
  /// the candidate `pairs` that are apart at the start and touch within the step (only when
  /// `search`, i.e. impacts are still allowed this step). Their speculative contacts leave
  /// `contacts` (the contacts of `pairs`; both sorted by pair), as the impacts take their place.
  void classify(const std::vector<ProxyPair>& pairs, const WorldShapes& start,
                const WorldShapes& end, const Ballistic& motion, double h, bool search,
                ContactSet& contacts);

  /// Pending impacts on bodies that take part in `contacts` become `speculative` contacts
  /// (made at placement `start` of state `s`; see solve_speculative), and so do impacts on bodies
  /// thereby added, until no pending impact touches a body of the contact solver; a body takes part
  /// when one of its contacts is engaged over the step of h [s]. The other contacts of bodies left
  /// with impacts are dropped: the impacts' own search covers them.
  void hand_over(const WorldShapes& start, const MotionState& s, double h, ContactSet& contacts,
                 ContactSet& speculative);

  /// After hand_over(), resolves the remaining impacts in time order, each at its t_c = t + τ,
  /// and logs them in `log` (`impacts` counts them against Settings::max_impacts_per_step).
  /// Each body an impact changes gets, in `start`, the state from which its ballistic path over
  /// the step passes through its state just after the impact; its shapes' placements follow: in
  /// `world_start` where the rest of the path starts (at the impact), in `end` where it ends.
  /// The other contacts of the changed bodies (in `contacts`, none of them engaged, since a
  /// changed body is not the solver's) are dropped, as hand_over() drops those of the bodies with
  /// impacts: they were made from the bodies' old paths. The search after each impact finds the
  /// changed bodies' impacts with the bodies outside the solver; with a body of the solver it
  /// only makes sure that neither can pass through the other within the step, and the next
  /// step's contact takes over. Returns false, leaving the step to be sub-stepped, when a changed
  /// path could carry a body through one of the solver's bodies within the step, or when impacts
  /// are left at the limit (the sub-steps then resolve the rest of the step's contacts at its
  /// end, as the limit promises, rather than leave those bodies with neither impact nor contact).
  bool resolve(double t, double h, MotionState& start, const StepAccelerations& acceleration,
               WorldShapes& world_start, WorldShapes& end, ContactSet& contacts, int& impacts,
               std::vector<Impact>& log);

 private:
  struct Pending {
    ProxyPair pair;
    double time;  ///< τ [s] from the start of the step
  };

  /// Whether a point of `c` (of `contacts`) overlaps or is within the slop.
  bool touching(const ContactSet& contacts, const Contact& c) const;
  /// Whether contact `c` (of `contacts`) can push during a step of h [s] from state `s`: a point
  /// touching, or closing its gap within the step.
  bool engaged(const ContactSet& contacts, const Contact& c, const MotionState& s, double h) const;
  bool in_solver(std::uint32_t shape) const { return marks_[shapes_[shape].body] & kInSolver; }
  bool changed(const ShapeRecord& shape) const { return marks_[shape.body] & kChanged; }
  /// Drops from `contacts` every contact of a dynamic body marked kWithImpact.
  void drop_contacts_with_impacts(ContactSet& contacts) const;
  /// Moves body b in `start` along its ballistic path from there by τ [s] (back for τ < 0).
  void follow_path(BodyId b, double tau, MotionState& start,
                   const StepAccelerations& acceleration) const;
  /// Finds the impacts from τ on of the shapes of the `changed` bodies, whose paths have changed,
  /// having placed them at τ in `rest_start` and at h in `end`; false when one of them could pass
  /// through a body of the contact solver.
  bool search_after(std::span<const BodyId> changed, double tau, double h, const Ballistic& motion,
                    WorldShapes& rest_start, WorldShapes& end);

  const BodyShapes& shapes_;
  const BodyInertia& inertia_;
  const std::vector<char>& dynamic_;
  const Settings& settings_;
  std::vector<Pending> pending_;
  // What hand_over() and resolve() learn of each body, one byte of these bits per body.
  enum Mark : std::uint8_t {
    kInSolver = 1,    // dynamic and in a contact of the solver this step
    kWithImpact = 2,  // in a pending impact after hand_over(), or changed by one in resolve()
    kChanged = 4,     // dynamic and in the impact being resolved
  };
  std::vector<std::uint8_t> marks_;
  // Scratch kept between steps so that impacts allocate nothing once the scene is warmed up.
  std::vector<ProxyPair> group_;
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
