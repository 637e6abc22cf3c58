#pragma once
// FR:Determine-Collision-Response-Over-Time for contacts that persist or rest, on velocities:
// sequential impulses with accumulated, clamped impulses and warm starting (the impulse of
// GD:impulse applied point by point until all contacts agree), friction where μ > 0
// (LC:Include-Dampening), and the bounce after them. The passes on positions are in
// position_passes.hpp.

#include <span>
#include <vector>

#include "engine/collision/body_shapes.hpp"
#include "engine/core.hpp"
#include "engine/solver/contact_batches.hpp"
#include "engine/solver/contact_set.hpp"
#include "scene/settings.hpp"

namespace gp {

/// One body's share of an entry K_ij of the effective-mass matrix of contact points [1/kg], for a
/// body of inverse mass `inverse_mass` [1/kg] and inverse moment `inverse_moment` [1/(kg·m²)] in
/// both points: the change of point i's v_rel·n through that body per unit normal impulse at point
/// j, (n_i·n_j)/m + (r_i × n_i)(r_j × n_j)/I (DD:impulseV, DD:torque, DD:chaslesThm), where
/// `directions` is n_i·n_j and `arm_i`, `arm_j` [m] are r × n, before the signs of A and B.
inline double body_coupling(double inverse_mass, double inverse_moment, double directions,
                            double arm_i, double arm_j) {
  return inverse_mass * directions + inverse_moment * arm_i * arm_j;
}

/// An entry K_ij of the effective-mass matrix of contact points [1/kg]: the change of point i's
/// v_rel·n per unit normal impulse at point j, summed over the bodies the two points share, A
/// counting + and B − (GD:impulse's denominator when i = j).
double normal_coupling(const Contact& ci, const ContactPointState& pi, const Contact& cj,
                       const ContactPointState& pj, const BodyInertia& m);

/// v_rel·d at a point whose arms crossed with the unit direction d are `arm_a` and `arm_b` [m],
/// from the bodies' relative velocity v_A − v_B (DD:chaslesThm, DD:reVeInColl, along d) [m/s].
inline double velocity_along(const Vec2& relative_velocity, double angular_velocity_a,
                             double angular_velocity_b, const Vec2& d, double arm_a, double arm_b) {
  return relative_velocity.dot(d) + angular_velocity_a * arm_a - angular_velocity_b * arm_b;
}

/// v_rel·n at point `p` of `c` in state `s` [m/s]: the normal component of the velocity of A's
/// material point relative to B's (DD:chaslesThm, DD:reVeInColl). Inline: a resting pile's survey
/// reads it for every point at every step.
inline double contact_normal_velocity(const MotionState& s, const Contact& c,
                                      const ContactPointState& p) {
  return velocity_along(s.velocity[c.body_a] - s.velocity[c.body_b], s.angular_velocity[c.body_a],
                        s.angular_velocity[c.body_b], c.normal, p.normal_arm_a, p.normal_arm_b);
}

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

/// The gap [m] under which a point counts as touching over a step of h [s] (target 0): closing a
/// gap of less than the passes' velocity tolerance times h changes no velocity by more than they
/// are asked to resolve, while in a settled pile, whose points lie 0.1 to 0.2 µm apart, closing
/// each by its own gap keeps the passes switching points between pushing and free at that scale.
double touching_gap(const Settings& settings, double h);

/// Prepares each point for a step of h [s]: its effective masses; its target normal velocity, the
/// speed that just closes the gap for points still apart, else 0; for touching points approaching
/// faster than the restitution threshold, the bounce C_R v_n from that approach velocity v_n
/// (measured in `before`, the state before the step's forces) for apply_restitution; and the
/// normal block of each two-point contact.
void prepare_contacts(ContactSet& contacts, const BodyShapes& shapes, const BodyInertia& inertia,
                      const MotionState& before, double h, const Settings& settings);
/// What prepare_contacts reads: the shapes, the inertias, the state before the step's forces
/// and the step h [s].
struct ContactPreparation {
  const BodyShapes& shapes;
  const BodyInertia& inertia;
  const MotionState& before;
  double h;
  const Settings& settings;
};

/// Applies the carried-over impulses of every point to the velocities of `s`.
void warm_start(const ContactSet& contacts, const BodyInertia& inertia, MotionState& s);

/// prepare_contacts, then warm_start into `s` (not `preparation.before`), contact by contact in
/// the order of `batches`, on the threads of the current task arena: one pass over the contacts
/// rather than two, with the same result, as preparing a contact reads no velocity of `s`.
/// Returns the deepest point's overlap [m] (ContactPointState::depth, negative where every point
/// is apart), −∞ without contacts.
double prepare_and_warm_start(const ContactBatches& batches, ContactSet& contacts,
                              const ContactPreparation& preparation, MotionState& s);

/// At most `iterations` passes of sequential impulses over the points' friction and normal
/// constraints (no bounce: restitution comes after, in apply_restitution), ending after the
/// first pass in which no contact's impulses changed its two bodies' velocities by more than
/// `tolerance` [m/s] (0: only a pass that changed nothing ends them). Returns the passes made.
int solve_velocities(ContactSet& contacts, const BodyInertia& inertia, int iterations,
                     double tolerance, MotionState& s);

/// How far the velocity passes go: at most `iterations` passes, ending after one that changed no
/// velocity by more than `tolerance` [m/s].
struct VelocityLimits {
  int iterations;
  double tolerance;
};

/// solve_velocities in the order of `batches` of `contacts`, each task's contacts by levels
/// (ContactBatches::Visit), on the threads of the current task arena; the same result on any
/// number of them. A level's or a colour's one-point contacts are solved four at a time where the
/// CPU has AVX2 (solve_single_points), with the same result.
int solve_velocities(const ContactBatches& batches, ContactSet& contacts,
                     const BodyInertia& inertia, const VelocityLimits& limits, MotionState& s);

/// One pass of sequential impulses over contact `c` of `contacts`, friction then normal, on the
/// velocities of `s`; returns the largest change it made to its two bodies' velocities [m/s].
double solve_contact_once(ContactSet& contacts, const Contact& c, const BodyInertia& inertia,
                          MotionState& s);

/// One pass that adds the bounce, −C_R times the approach velocity, to each point that was
/// approaching and took an impulse. A separate pass after the others (as in Box2D 3) rather than
/// a target inside them: simultaneous targets make a body pinned between two contacts (a disc
/// struck against a wall) bounce off both at once, which creates energy.
void apply_restitution(ContactSet& contacts, const BodyInertia& inertia, MotionState& s);
/// apply_restitution in the order of `batches` of `contacts`, on the threads of the current task
/// arena.
void apply_restitution(const ContactBatches& batches, ContactSet& contacts,
                       const BodyInertia& inertia, MotionState& s);

}  // namespace gp
