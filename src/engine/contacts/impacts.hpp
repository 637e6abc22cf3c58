#pragma once
// Continuous collision: finds the time of impact t_c of a pair of bodies inside a step (the t_c
// of IM:col2D) and resolves the impact there, so that the rest of the step is integrated after
// it; a fast body cannot pass through a thin wall between two steps.

#include <optional>
#include <span>
#include <vector>

#include "engine/collision/broadphase.hpp"
#include "engine/contacts/body_shapes.hpp"
#include "engine/contacts/contact_solver.hpp"
#include "engine/dynamics/force_model.hpp"

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
  StepAccelerations acceleration;

  /// Transform of `body` after τ [s].
  Vec2 position(BodyId body, double tau) const;
  double angle(BodyId body, double tau) const;
  /// Velocities of `body` after τ [s].
  Vec2 velocity(BodyId body, double tau) const;
  double angular_velocity(BodyId body, double tau) const;
};

/// Fastest any point of shape `a` can move towards any point of shape `b` during a step of h [s]
/// along `motion`, a bound [m/s].
double closing_speed_bound(const ShapeRecord& a, const ShapeRecord& b, const Ballistic& motion,
                           double h);

/// Which pairs the time-of-impact search leaves to the contact solver.
struct ImpactFilter {
  double slop;       ///< m: pairs closer than this at the start are in contact already
  double min_speed;  ///< m/s: within `margin`, pairs closing slower than this are contacts
  double margin;     ///< m: the contact solver's speculative margin
};

/// The filter of a space's settings: its slop, restitution threshold and contact margin.
inline ImpactFilter impact_filter(const Settings& settings) {
  return {settings.linear_slop, settings.restitution_threshold, settings.contact_margin};
}

/// The earliest τ in (t0, h] at which shapes `a` and `b`, apart at τ = t0 (signed distance >
/// `filter.slop`), touch while following `motion`; nothing if they do not. Pairs closer than
/// `filter.margin` that close slower than `filter.min_speed` over the rest of the step are left
/// to the contact solver's speculative contacts, as they bounce no more than resting contacts
/// (restitution threshold). `a0`, `b0` and `a1`, `b1` are the shapes placed at τ = t0 and τ = h.
std::optional<double> impact_time(const ShapeRecord& a, const ShapeRecord& b,
                                  const WorldShapeView& a0, const WorldShapeView& b0,
                                  const WorldShapeView& a1, const WorldShapeView& b1,
                                  const Ballistic& motion, double t0, double h,
                                  const ImpactFilter& filter);

/// Impacts this close in time [s] over a step of h [s] count as simultaneous.
inline double simultaneity(double h) {
  return 1e-12 + 1e-9 * h;
}

class ImpactSearch {
 public:
  /// The earliest impact_time() from τ = 0 of any of `pairs`, nothing if none. `start` and
  /// `end` are the shapes placed at τ = 0 and at τ = h along `motion`.
  std::optional<double> earliest(const std::vector<ProxyPair>& pairs, const BodyShapes& shapes,
                                 const WorldShapes& start, const WorldShapes& end,
                                 const Ballistic& motion, double h, const ImpactFilter& filter);

  /// The pairs found touching at the earliest time by the last call to earliest().
  const std::vector<ProxyPair>& touching() const { return touching_; }

 private:
  std::vector<ProxyPair> touching_;
};

/// Resolves the impacts of `pairs` in state `s` at time `t`: the pairs' contacts get the impulse
/// of IM:col2D (one point), or sequential impulses iterated to convergence with the same
/// restitution targets (two points, or several pairs at once). Appends what it did to `log`.
/// `contacts` is scratch, kept by the caller so that an impact allocates nothing.
void resolve_impacts(std::span<const ProxyPair> pairs, const BodyShapes& shapes,
                     const BodyInertia& inertia, const Settings& settings, double t, MotionState& s,
                     ContactSet& contacts, std::vector<Impact>& log);

}  // namespace gp
