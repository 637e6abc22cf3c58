#pragma once
// FR:Simulation-Space: the space that owns the bodies and the settings, and advances them in time
// (FR:Calculate-Translation-Over-Time, FR:Calculate-Rotation-Over-Time, FR:Determine-Collisions,
// FR:Determine-Collision-Response-Over-Time).

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core.hpp"
#include "engine/force_callback.hpp"
#include "engine/impact.hpp"
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
  bool removed(BodyId body) const;
  /// The body named `name` that is not removed (the first added, if several), or nothing; O(N).
  std::optional<BodyId> find_body(std::string_view name) const;

  double time() const;
  std::size_t body_count() const;
  std::string_view name(BodyId body) const;
  BodyType type(BodyId body) const;
  /// kg; infinite for static and kinematic bodies.
  double mass(BodyId body) const;
  /// kg·m² about the centre of mass; infinite for bodies that cannot rotate.
  double moment(BodyId body) const;
  /// Centre of mass, orientation in [0, 2π), velocities.
  BodyState state(BodyId body) const;
  const Settings& settings() const;

  /// The stages of a step, in the order it runs them, each with its SRS ids, whether this space
  /// needs it (the step skips those it does not), how often it ran and, while timed, for how long.
  std::vector<PipelineStage> pipeline() const;
  /// Whether the steps from now on time each of their stages (PipelineStage::seconds); off by
  /// default.
  void time_stages(bool on);

  /// The impacts resolved at their time of impact during the last step.
  const std::vector<Impact>& impacts() const;
  /// The points of the contact constraints of the last sub-step, with the impulses the solver
  /// accumulated there.
  std::vector<ContactPointReport> contact_points() const;

 private:
  friend struct SpaceInternals;
  struct Impl;

  /// "bodies[i]" for a body of the space that is not removed; else throws InputError.
  std::string field_of(BodyId body) const;
  /// field_of(body), and throws InputError unless `body` is dynamic: `what` is done to it.
  std::string dynamic_field_of(BodyId body, const std::string& what) const;

  std::unique_ptr<Impl> impl_;
};

}  // namespace gp
