#pragma once
// Continuous collision: finds the time of impact t_c of a pair of bodies inside a step (the t_c
// of IM:col2D) and resolves the impact there, so that the rest of the step is integrated after
// it; a fast body cannot pass through a thin wall between two steps.

#include <optional>
#include <vector>

#include "engine/collision/broadphase.hpp"
#include "engine/contacts/body_shapes.hpp"
#include "engine/contacts/contact_solver.hpp"

namespace gp {

/// A collision resolved at its time of impact.
struct Impact {
  double time;  ///< t_c [s]
  BodyId body_a;
  BodyId body_b;
  Vec2 normal;     ///< unit, from B towards A
  Vec2 point;      ///< m, world (the mean of the contact points)
  double impulse;  ///< j [N·s], the sum over the contact points
};

/// Motion of a body over a step under its accelerations at the start of the step: exact for
/// constant accelerations, and what the time-of-impact search follows.
struct Ballistic {
  const MotionState& start;
  const Accelerations& acceleration;

  /// Transform of `body` after τ [s].
  Vec2 position(BodyId body, double tau) const;
  double angle(BodyId body, double tau) const;
};

class ImpactSearch {
 public:
  /// The earliest τ in (0, h] at which a pair of `pairs` that is apart at the start (signed
  /// distance > `slop` [m]) touches; nothing if no such pair does. Pairs closer than `margin` [m]
  /// that close slower than `min_speed` [m/s] over the step are left to the contact solver's
  /// speculative contacts, as they bounce no more than resting contacts (restitution threshold).
  /// `start` and `end` are the shapes placed at τ = 0 and at τ = h along `motion`.
  std::optional<double> earliest(const std::vector<ProxyPair>& pairs, const BodyShapes& shapes,
                                 const std::vector<WorldShape>& start,
                                 const std::vector<WorldShape>& end, const Ballistic& motion,
                                 double h, double slop, double min_speed, double margin);

  /// The pairs found touching at the earliest time by the last call to earliest().
  const std::vector<ProxyPair>& touching() const { return touching_; }

 private:
  std::optional<double> time_of_impact(const ShapeRecord& a, const ShapeRecord& b, double d0,
                                       double d1, const Ballistic& motion, double h) const;
  std::vector<ProxyPair> touching_;
};

/// Resolves the impacts of `pairs` in state `s` at time `t`: the pairs' contacts get the impulse
/// of IM:col2D (one point), or sequential impulses iterated to convergence with the same
/// restitution targets (two points, or several pairs at once). Appends what it did to `log`.
void resolve_impacts(const std::vector<ProxyPair>& pairs, const BodyShapes& shapes,
                     const BodyInertia& inertia, const Settings& settings, double t, MotionState& s,
                     std::vector<Impact>& log);

}  // namespace gp
