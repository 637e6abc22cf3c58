#pragma once
// FR:Simulation-Space: the space that owns the bodies and the settings, and advances them in time
// (FR:Calculate-Translation-Over-Time, FR:Calculate-Rotation-Over-Time, FR:Determine-Collisions,
// FR:Determine-Collision-Response-Over-Time).

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/body_names.hpp"
#include "engine/body_state.hpp"
#include "engine/contacts/body_shapes.hpp"
#include "engine/contacts/collision_detection.hpp"
#include "engine/contacts/contact_solver.hpp"
#include "engine/contacts/impacts.hpp"
#include "engine/contacts/island_solver.hpp"
#include "engine/contacts/local_impacts.hpp"
#include "engine/contacts/warm_start.hpp"
#include "engine/dynamics/force_model.hpp"
#include "engine/dynamics/integrator.hpp"
#include "engine/pipeline.hpp"
#include "scene/body.hpp"
#include "scene/settings.hpp"

namespace gp {

class Space {
 public:
  /// Throws InputError if the settings break a constraint.
  explicit Space(const Settings& settings = {});
  ~Space();
  Space(const Space&) = delete;
  Space& operator=(const Space&) = delete;

  /// Adds a body; throws InputError naming "bodies[i].field" when `def` breaks an SRS data
  /// constraint or describes a degenerate shape (FR:Verify-Physical_Constraints). Body ids count
  /// from 0 in the order of adding.
  BodyId add_body(const BodyDef& def);

  /// A time-dependent force and torque on a dynamic body, added to its constant ones.
  void set_force_callback(BodyId body, ForceCallback callback);

  /// Advances the space by dt [s] > 0. Throws NumericalError if a state becomes non-finite.
  void step(double dt);

  // Changes between steps (space_edits.cpp). Each checks its input as add_body does: it throws
  // InputError naming "bodies[i].field", the rule and the value, having changed nothing, for a
  // body that is not in the space or a value that breaks a constraint.

  /// Moves the centre of mass of `body` (the position that state() reports) to `position` [m].
  void set_position(BodyId body, const Vec2& position);
  /// Turns `body` about its centre of mass to orientation ϕ = `angle` [rad].
  void set_angle(BodyId body, double angle);
  /// The velocity of the centre of mass [m/s]; not of a static body.
  void set_velocity(BodyId body, const Vec2& velocity);
  /// ω [rad/s]; not of a static body, nor, unless 0, of a dynamic body without a moment of
  /// inertia (a point mass given none).
  void set_angular_velocity(BodyId body, double angular_velocity);
  /// Applies impulse J [N·s] at world point p [m] to dynamic body `body`: its velocity changes by
  /// J/m (DD:impulseV) and its ω by (r × J)/I, r from its centre of mass to p (DD:torque).
  void apply_impulse(BodyId body, const Vec2& impulse, const Vec2& point);
  /// Applies force F [N] at world point p [m] to dynamic body `body` during the next step() only:
  /// F at the centre of mass and the torque r × F (DD:torque), r from the centre of mass as it
  /// is now, both constant over that step (as Box2D's ApplyForce and Pymunk's
  /// apply_force_at_world_point). Forces applied before one step add up.
  void apply_force(BodyId body, const Vec2& force, const Vec2& point);
  /// Removes `body`: it no longer moves, collides, pulls or is reported by find_body. Its contacts
  /// and their warm starts go with it; ids are not reused, and the other bodies keep theirs.
  void remove_body(BodyId body);
  bool removed(BodyId body) const { return removed_[body] != 0; }
  /// The body named `name` that is not removed (the first added, if several), or nothing; O(N).
  std::optional<BodyId> find_body(std::string_view name) const;

  double time() const { return time_; }
  std::size_t body_count() const { return names_.size(); }
  std::string_view name(BodyId body) const { return names_[body]; }
  BodyType type(BodyId body) const { return types_[body]; }
  /// kg; infinite for static and kinematic bodies.
  double mass(BodyId body) const;
  /// kg·m² about the centre of mass; infinite for bodies that cannot rotate.
  double moment(BodyId body) const;
  /// Centre of mass, orientation in [0, 2π), velocities.
  BodyState state(BodyId body) const;
  const Settings& settings() const { return settings_; }

  /// The stages a step runs for this space, with their SRS ids.
  std::vector<PipelineStage> pipeline() const;

  /// The impacts resolved at their time of impact during the last step.
  const std::vector<Impact>& impacts() const { return impacts_; }
  /// The contact constraints of the last sub-step, with the impulses the solver accumulated.
  const ContactSet& contacts() const { return contacts_; }

  /// The space's own models, for a verifier that integrates the same equations another way
  /// (the SUNDIALS oracle): the force model (IM:transMot, IM:rotMot right-hand sides), the shapes
  /// centred on their bodies' centres of mass, the inverse masses and the state of every body.
  const ForceModel& force_model() const { return forces_; }
  const BodyShapes& shapes() const { return shapes_; }
  const BodyInertia& inertia() const { return inertia_; }
  const MotionState& motion_state() const { return state_; }

 private:
  /// Advances by h, or by less when an impact comes first; returns the time advanced [s].
  double substep(double h);
  /// Advances by h in one piece, resolving impacts for their own bodies only (LocalImpacts);
  /// false, having changed nothing, when the step must be sub-stepped instead.
  bool local_step(double h);
  /// The ballistic motion from start_ under the accelerations at the start of the step: under
  /// constant forces the ForceModel's, else evaluated into varying_acceleration_.
  Ballistic start_motion();
  /// The factor the previous step's impulses carry over with into a step of h [s].
  double warm_start_scale(double h) const;
  /// Places the shapes at the start of a step of h and at the end of their ballistic paths, and
  /// returns the candidate pairs of the boxes swept between.
  const std::vector<ProxyPair>& sweep(double h, const Ballistic& motion);
  /// Integrates over h from state_, then solves contacts_ (and speculative_contacts_) and keeps
  /// their impulses for warm starting.
  void advance(double h);
  void move_kinematic(double h);
  /// "bodies[i]" for a body of the space that is not removed; else throws InputError.
  std::string field_of(BodyId body) const;
  /// field_of(body), and throws InputError unless `body` is dynamic: `what` is done to it.
  std::string dynamic_field_of(BodyId body, const std::string& what) const;

  Settings settings_;
  double time_ = 0.0;
  BodyNames names_;
  std::vector<BodyType> types_;
  std::vector<char> dynamic_;
  std::vector<char> removed_;
  std::vector<BodyId> kinematic_;
  bool collides_ = false;  // two shapes of different bodies, one of them dynamic
  std::size_t bodies_with_shapes_ = 0;
  bool dynamic_with_shapes_ = false;  // a dynamic body has a shape
  BodyInertia inertia_;
  MotionState state_;
  ForceModel forces_;
  std::unique_ptr<Integrator> integrator_;
  BodyShapes shapes_;
  CollisionDetection detection_;
  ImpactSearch impact_search_;
  LocalImpacts local_impacts_{shapes_, inertia_, dynamic_, settings_};
  std::vector<Impact> impacts_;
  int impacts_this_step_ = 0;
  double previous_h_ = 0.0;
  // Scratch kept between steps so that a step does not allocate once the scene is warmed up.
  MotionState start_;
  Accelerations varying_acceleration_;  // at the start, when the forces are not constant
  WorldShapes world_start_, world_end_;
  ContactSet contacts_, impact_scratch_;
  std::vector<WarmStart> warm_starts_;  // the impulses of the last sub-step's contacts
  ContactSet speculative_contacts_;     // impacts on resting bodies, this step only
  SpeculativeScratch speculative_scratch_;
  IslandScratch island_scratch_;
  std::vector<ProxyPair> contact_pairs_;
  RotationCache rotations_;
};

}  // namespace gp
