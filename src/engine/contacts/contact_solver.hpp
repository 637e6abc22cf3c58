#pragma once
// FR:Determine-Collision-Response-Over-Time for contacts that persist or rest: sequential impulses
// with accumulated, clamped impulses and warm starting (the impulse of GD:impulse applied point by
// point until all contacts agree), friction where μ > 0 (LC:Include-Dampening), and penetration
// removal by moving positions only, which adds no energy.

#include <vector>

#include "engine/contacts/contact.hpp"
#include "engine/dynamics/motion_state.hpp"
#include "engine/geometry/transform.hpp"
#include "engine/settings.hpp"

namespace gp {

/// Inverse masses [1/kg] and moments [1/(kg·m²)] by body id; 0 for bodies collisions cannot
/// move or turn.
struct BodyInertia {
  std::vector<double> inverse_mass;
  std::vector<double> inverse_moment;
};

/// Velocity of A's material point relative to B's at contact point `p` of `c` in state `s`
/// [m/s] (DD:chaslesThm, DD:reVeInColl).
Vec2 contact_relative_velocity(const MotionState& s, const Contact& c, const ContactPointState& p);

/// Prepares each point for a step of h [s]: its effective masses; its target normal velocity, the
/// speed that just closes the gap for points still apart, else 0; and, for touching points
/// approaching faster than the restitution threshold, that approach velocity v_n (measured in
/// `before`, the state before the step's forces) for apply_restitution.
void prepare_contacts(std::vector<Contact>& contacts, const BodyInertia& inertia,
                      const MotionState& before, double h, const Settings& settings);

/// Applies the carried-over impulses of every point to the velocities of `s`.
void warm_start(const std::vector<Contact>& contacts, const BodyInertia& inertia, MotionState& s);

/// `iterations` passes of sequential impulses over the points' friction and normal constraints
/// (no bounce: restitution comes after, in apply_restitution).
void solve_velocities(std::vector<Contact>& contacts, const BodyInertia& inertia, int iterations,
                      MotionState& s);

/// One pass that adds the bounce, −C_R times the approach velocity, to each point that was
/// approaching and took an impulse. A separate pass after the others (as in Box2D 3) rather than
/// a target inside them: simultaneous targets make a body pinned between two contacts (a disc
/// struck against a wall) bounce off both at once, which creates energy.
void apply_restitution(std::vector<Contact>& contacts, const BodyInertia& inertia, MotionState& s);

/// `iterations` passes that move and turn bodies apart (positions only) where the contact points
/// overlap by more than `slop` [m], removing a fifth of the excess per pass (Baumgarte's 0.2).
/// `rotations` is scratch space for each body's rotation, kept by the caller so that a step does
/// not allocate.
void correct_positions(const std::vector<Contact>& contacts, const BodyInertia& inertia,
                       int iterations, double slop, MotionState& s,
                       std::vector<Transform>& rotations);

}  // namespace gp
