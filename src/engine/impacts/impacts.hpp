#pragma once
// Continuous collision: finds the time of impact t_c of a pair of bodies inside a step (the t_c
// of IM:col2D) and resolves the impact there, so that the rest of the step is integrated after
// it; a fast body cannot pass through a thin wall between two steps.

#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "engine/collision/body_shapes.hpp"
#include "engine/collision/broadphase.hpp"
#include "engine/dynamics/force_model.hpp"
#include "engine/dynamics/integrator.hpp"
#include "engine/impact.hpp"
#include "engine/solver/velocity_passes.hpp"

namespace gp {

struct StepContext;

/// Motion of a body over a step of h under its accelerations at the start of the step, along the
/// path the integrator takes (exact for constant accelerations), which the time-of-impact search
/// follows. On the straight path of symplectic Euler, the velocity after τ > 0 is the step's end
/// velocity v₀ + ah, and followed back (τ < 0) from a state moving at v it is v − ah: the start
/// from which a step passes through that state.
struct Ballistic {
  Ballistic(const MotionState& from, StepAccelerations accelerations,
            PathShape path = PathShape::kParabola, double h = 0.0)
      : start(from), acceleration(accelerations), shape(path), step(h) {}

  const MotionState& start;
  StepAccelerations acceleration;
  PathShape shape;
  double step;  ///< s, the step's h (for the straight path)

  /// Transform of `body` after τ [s].
  Vec2 position(BodyId body, double tau) const;
  double angle(BodyId body, double tau) const;
  /// The angle [rad] `body` turns through over τ [s]: angle() is its start orientation turned by
  /// it, and kept within a turn.
  double turn(BodyId body, double tau) const;
  /// Velocities of `body` after τ [s].
  Vec2 velocity(BodyId body, double tau) const;
  double angular_velocity(BodyId body, double tau) const;
  /// Where `shape` is after τ [s] (ShapeRecord::frame), and the shape placed there.
  Transform frame(const ShapeRecord& shape, double tau) const {
    return shape.frame(position(shape.body, tau), angle(shape.body, tau));
  }
  WorldShape placed(const ShapeRecord& shape, double tau) const {
    return to_world(shape.local, frame(shape, tau));
  }
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

/// A shape with its placement at the start of a window of the step (its placement at the end
/// is made only for the few pairs that get as far as needing it).
struct SweptShape {
  const ShapeRecord& shape;
  const WorldShapeView& at_t0;
};

/// The part (t0, h] of a step that a search covers [s, from the start of the step].
struct StepWindow {
  double t0;
  double h;
};

/// A pair's first touch in a window, as find_touch finds it: the shapes' signed distance at t0,
/// and the touch's time, or, for shapes that overlap at h, their signed distance there: the touch
/// then surely lies between, and touch_time() searches for it when asked, as a caller that hands
/// the impact over to the contact solver never needs its time.
struct Touch {
  double time = std::numeric_limits<double>::quiet_NaN();  ///< τ [s]; NaN until searched for
  double distance_t0 = 0.0;                                ///< m, above the filter's slop
  double distance_h = 0.0;                                 ///< m, ≤ 0 where not searched for
  bool searched() const { return !std::isnan(time); }
};

/// Whether shapes `a` and `b`, apart at τ = t0 (signed distance > `filter.slop`), touch in (t0, h]
/// while following `motion`; nothing if they do not. Pairs closer than `filter.margin` that close
/// slower than `filter.min_speed` over the rest of the step are left to the contact solver's
/// speculative contacts, as they bounce no more than resting contacts (restitution threshold).
std::optional<Touch> find_touch(const SweptShape& a, const SweptShape& b, const Ballistic& motion,
                                const StepWindow& window, const ImpactFilter& filter);

/// The earliest τ in (t0, h] at which the shapes of `touch`, found by find_touch with the same
/// shapes, motion and window, touch: its time, or, not yet searched for, the root of their
/// signed distance between the bracket's ends.
double touch_time(const Touch& touch, const ShapeRecord& a, const ShapeRecord& b,
                  const Ballistic& motion, const StepWindow& window);

/// find_touch, with the touch's time.
std::optional<double> impact_time(const SweptShape& a, const SweptShape& b, const Ballistic& motion,
                                  const StepWindow& window, const ImpactFilter& filter);

/// Impacts this close in time [s] over a step of h [s] count as simultaneous.
inline double simultaneity(double h) {
  return 1e-12 + 1e-9 * h;
}

class ImpactSearch {
 public:
  /// The earliest impact_time() over the sub-step of any of the context's candidate pairs,
  /// nothing if none, from the shapes placed at its start and end along its motion.
  std::optional<double> earliest(const StepContext& c);

  /// The pairs found touching at the earliest time by the last call to earliest().
  const std::vector<ShapePair>& touching() const { return touching_; }

 private:
  std::vector<ShapePair> touching_;
};

/// Resolves the impacts of `pairs` in state `s` at time `t`: the pairs' contacts get the impulse
/// of IM:col2D (one point), or sequential impulses iterated to convergence with the same
/// restitution targets (two points, or several pairs at once). Appends what it did to the
/// context's impacts. `contacts` is scratch, kept by the caller so that an impact allocates
/// nothing.
void resolve_impacts(std::span<const ShapePair> pairs, StepContext& ctx, double t, MotionState& s,
                     ContactSet& contacts);

}  // namespace gp
