#pragma once
// FR:Determine-Collision-Response-Over-Time for contacts that persist or rest: sequential impulses
// with accumulated, clamped impulses and warm starting (the impulse of GD:impulse applied point by
// point until all contacts agree), friction where μ > 0 (LC:Include-Dampening), and penetration
// removal by moving positions only, which adds no energy.

#include <vector>

#include "engine/contacts/contact.hpp"
#include "engine/dynamics/motion_state.hpp"
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

/// Prepares each point for a step of h [s]: its effective masses, and its target normal velocity:
/// −C_R v_n for touching points approaching faster than the restitution threshold (v_n measured
/// in `before`, the state before the step's forces), the speed that just closes the gap for points
/// still apart, else 0.
void prepare_contacts(std::vector<Contact>& contacts, const BodyInertia& inertia,
                      const MotionState& before, double h, const Settings& settings);

/// Applies the carried-over impulses of every point to the velocities of `s`.
void warm_start(const std::vector<Contact>& contacts, const BodyInertia& inertia, MotionState& s);

/// `iterations` passes of sequential impulses over the points' friction and normal constraints.
void solve_velocities(std::vector<Contact>& contacts, const BodyInertia& inertia, int iterations,
                      MotionState& s);

/// `iterations` passes that move and turn bodies apart (positions only) where the contact points
/// overlap by more than `slop` [m], removing a fifth of the excess per pass (Baumgarte's 0.2).
void correct_positions(const std::vector<Contact>& contacts, const BodyInertia& inertia,
                       int iterations, double slop, MotionState& s);

}  // namespace gp
