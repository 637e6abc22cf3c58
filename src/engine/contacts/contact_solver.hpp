#pragma once
// FR:Determine-Collision-Response-Over-Time for contacts that persist or rest: sequential impulses
// with accumulated, clamped impulses and warm starting (the impulse of GD:impulse applied point by
// point until all contacts agree), friction where μ > 0 (LC:Include-Dampening), and penetration
// removal by moving positions only, which adds no energy.

#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "engine/contacts/body_shapes.hpp"
#include "engine/contacts/contact_set.hpp"
#include "engine/dynamics/motion_state.hpp"
#include "engine/geometry/transform.hpp"
#include "scene/settings.hpp"

namespace gp {

/// Inverse masses [1/kg] and moments [1/(kg·m²)] by body id; 0 for bodies collisions cannot
/// move or turn.
struct BodyInertia {
  std::vector<double> inverse_mass;
  std::vector<double> inverse_moment;
};

/// An entry K_ij of the effective-mass matrix of contact points [1/kg]: the change of point i's
/// v_rel·n per unit normal impulse at point j, summed over the bodies the two points share, A
/// counting + and B − (GD:impulse's denominator when i = j).
double normal_coupling(const Contact& ci, const ContactPointState& pi, const Contact& cj,
                       const ContactPointState& pj, const BodyInertia& m);

/// v_rel·n at point `p` of `c` in state `s` [m/s]: the normal component of the velocity of A's
/// material point relative to B's (DD:chaslesThm, DD:reVeInColl).
double contact_normal_velocity(const MotionState& s, const Contact& c, const ContactPointState& p);

/// Applies the impulse `normal` n + `tangent` t [N·s] at point `p` to A and the reaction to B
/// (DD:impulseV, DD:torque, TM:NewtonThirdLawMot), with the point's arms.
void apply_contact_impulse(const Contact& c, const ContactPointState& p, double normal,
                           double tangent, const BodyInertia& inertia, MotionState& s);

/// IM:col2D at point `p` of `c` in state `s`: the impulse j n that gives the point's normal
/// velocity −C_R times its value before, applied to both bodies' velocities; returns j [N·s].
double apply_collision_response(const Contact& c, const ContactPointState& p, double restitution,
                                const BodyInertia& inertia, MotionState& s);

/// The coefficient of restitution C_R of contact `c`: the larger of its two shapes' (the
/// combination rule of FR:Input-Surface-Properties, as Box2D's).
double contact_restitution(const BodyShapes& shapes, const Contact& c);

/// Impacts among bodies already touching, a Newton's cradle at rest struck at one end: resolved
/// pair after pair by apply_collision_response with each contact's C_R, pass after pass, until
/// no touching point with C_R > 0 approaches faster than the restitution threshold (at most as
/// many passes as the solver's velocity iterations). This is the sequential model of simultaneous
/// impacts, under which the cradle passes the momentum along the row to its last ball, where a
/// simultaneous solve spreads it over the row. Returns whether any impulse was applied.
bool propagate_impacts(const ContactSet& contacts, const BodyShapes& shapes,
                       const BodyInertia& inertia, const Settings& settings, MotionState& s);

/// Prepares each point for a step of h [s]: its effective masses; its target normal velocity, the
/// speed that just closes the gap for points still apart, else 0; for touching points approaching
/// faster than the restitution threshold, the bounce C_R v_n from that approach velocity v_n
/// (measured in `before`, the state before the step's forces) for apply_restitution; and the
/// normal block of each two-point contact.
void prepare_contacts(ContactSet& contacts, const BodyShapes& shapes, const BodyInertia& inertia,
                      const MotionState& before, double h, const Settings& settings);

/// Applies the carried-over impulses of every point to the velocities of `s`.
void warm_start(const ContactSet& contacts, const BodyInertia& inertia, MotionState& s);

/// At most `iterations` passes of sequential impulses over the points' friction and normal
/// constraints (no bounce: restitution comes after, in apply_restitution), ending after the
/// first pass in which no contact's impulses changed its two bodies' velocities by more than
/// `tolerance` [m/s] (0: only a pass that changed nothing ends them). Returns the passes made.
int solve_velocities(ContactSet& contacts, const BodyInertia& inertia, int iterations,
                     double tolerance, MotionState& s);

/// One pass that adds the bounce, −C_R times the approach velocity, to each point that was
/// approaching and took an impulse. A separate pass after the others (as in Box2D 3) rather than
/// a target inside them: simultaneous targets make a body pinned between two contacts (a disc
/// struck against a wall) bounce off both at once, which creates energy.
void apply_restitution(ContactSet& contacts, const BodyInertia& inertia, MotionState& s);

/// Moves and turns the bodies by the velocity changes of the contacts' accumulated impulses
/// (DD:impulseV, DD:torque) kept up for `duration` [s]: share × h for impulses that act over a
/// step of h like forces (the integrator's impulse_position_share). A negative duration takes a
/// displacement back.
void move_by_contact_impulses(const ContactSet& contacts, const BodyInertia& inertia,
                              double duration, MotionState& s);

/// Scratch for solve_speculative, kept by the caller so that a step does not allocate.
struct SpeculativeScratch {
  std::vector<char> reached;        // per body
  std::vector<char> included;       // per resting contact
  std::vector<std::size_t> nearby;  // resting contacts solved with the impacts
  std::vector<BodyId> newly;
};

/// Impacts the contact solver takes on after the resting contacts are solved: `speculative`
/// points, still apart at the start of the step of h [s], whose bodies also rest on others (see
/// LocalImpacts). They are solved together with the resting contacts within a few contacts of
/// them for `iterations` passes, and bounce by C_R after; the impulses this adds act from the
/// impact on, so they move the bodies by h × Δv, which closes each gap exactly, rather than by
/// the resting share, which would leave a fast body overlapping and press the body under it
/// into the ground.
void solve_speculative(ContactSet& resting, ContactSet& speculative, const BodyShapes& shapes,
                       const BodyInertia& inertia, const MotionState& before, double h,
                       const Settings& settings, MotionState& s, SpeculativeScratch& scratch);

/// The rotations of bodies by an angle each (in the position passes, the angle each has turned
/// since its contacts were found), each computed only when first asked for, and after a small
/// turn updated without trigonometry: most contact points of discs need none, and position passes
/// turn bodies by tiny angles.
class RotationCache {
 public:
  /// Forgets every rotation; sized for `bodies` bodies.
  void reset(std::size_t bodies);
  /// `body` was turned by `turn` [rad] to `angle` [rad]: its rotation follows, or is forgotten
  /// after a turn too large for the series.
  void turn(BodyId body, double angle, double turn) {
    // Beyond this, the series of Rotation::turned_slightly errs by more than 1e-13 rad.
    constexpr double kSmallTurn = 1e-3;
    if (turn == 0.0 || std::isnan(angle_[body])) return;
    if (std::abs(turn) > kSmallTurn) {
      angle_[body] = std::numeric_limits<double>::quiet_NaN();
      return;
    }
    rotation_[body] = rotation_[body].turned_slightly(turn);
    angle_[body] = angle;
  }
  /// `v` turned by `angle` [rad], the current angle of `body`.
  Vec2 rotate(BodyId body, double angle, const Vec2& v) {
    if (angle_[body] != angle) {
      angle_[body] = angle;
      rotation_[body] = Rotation(angle);
    }
    return rotation_[body].rotate(v);
  }

 private:
  std::vector<double> angle_;  // rad, the angle each rotation is for; NaN: none yet
  std::vector<Rotation> rotation_;
};

/// At most `iterations` passes that move and turn bodies apart (positions only) where the
/// contact points overlap by more than `slop` [m], removing a fifth of the excess per pass
/// (Baumgarte's 0.2); they end after a pass that found no overlap deeper than two slops. The
/// overlap is measured between each body's deepest point inside the other at detection, carried
/// along as the body moved and turned from `detected_angle` [rad, by body id], its angle when the
/// contacts were found. `rotations` is scratch, kept by the caller so that a step does not
/// allocate.
void correct_positions(const ContactSet& contacts, const BodyShapes& shapes,
                       const BodyInertia& inertia, std::span<const double> detected_angle,
                       int iterations, double slop, MotionState& s, RotationCache& rotations);

}  // namespace gp
