#pragma once
// The settings of a Space: the forces of the world, the integrator and the contact solver.

#include <optional>
#include <string>
#include <string_view>

#include "gamephysics/models/types.hpp"

namespace gp {

/// The game integrators behind one interface (LC:Variable-ODE-Solver).
enum class IntegratorKind { SymplecticEuler, VelocityVerlet, RK4 };

/// "symplectic_euler", "velocity_verlet", "rk4".
std::string_view integrator_name(IntegratorKind kind);
/// The kind named `name`, or nothing.
std::optional<IntegratorKind> integrator_from_name(std::string_view name);

struct Settings {
  Vec2 gravity = Vec2::Zero();  ///< g [m/s²], uniform
  std::optional<double> G;      ///< gravitational constant [m³/(kg·s²)]: pairwise gravitation
  /// Velocity Verlet by default: second order, symplectic, one force evaluation per step, and
  /// exact under constant acceleration (free flight under gravity and constant forces).
  IntegratorKind integrator = IntegratorKind::VelocityVerlet;
  int velocity_iterations = 10;  ///< sequential-impulse passes over the contacts per step, at most
  /// m/s: the sequential-impulse passes of a step end early once a whole pass changes no body's
  /// velocity by more than this; a resting stack, warm-started with last step's impulses, then
  /// needs a pass or two instead of all of them.
  double velocity_tolerance = 1e-5;
  /// Islands of contacts (joined through the dynamic bodies they share) with at most this many
  /// points get their normal impulses solved exactly, all at once, before the passes; 0: never,
  /// for any island.
  /// Sequential impulses alone let a light body under a heavy one sink.
  int direct_solve_points = 64;
  /// Islands whose heaviest dynamic body is more than direct_solve_mass_ratio times as heavy as
  /// their lightest get the same exact solve up to this many points (while direct_solve_points is
  /// not 0): sequential impulses converge ever slower as masses differ, so that a pyramid under a
  /// box 200 times denser leans and sinks by tens of centimetres, while piles of even masses do
  /// well with them at a fraction of the cost.
  int direct_solve_uneven_points = 512;
  double direct_solve_mass_ratio = 10.0;  ///< the mass ratio above which an island is uneven
  /// Islands at rest (every body slower than sleep_speed and sleep_angular_speed, no point
  /// overlapping by more than linear_slop) whose carried-over impulses do not hold them get the
  /// same solve up to this many points: a pile set down
  /// at once, or knocked, which sequential impulses would take hundreds of steps to settle, a
  /// 100-row pyramid sinking 1.4 m on the way. Once held, the passes keep it in a pass or two.
  int direct_solve_resting_points = 32768;
  int position_iterations = 4;  ///< penetration-removal passes per step
  /// Impacts slower than this [m/s] are treated as resting contact (no bounce), which ends the
  /// infinite sequence of ever smaller bounces (a Zeno sequence) of an inelastic ball.
  double restitution_threshold = 0.05;
  /// At most this many impacts per step are resolved at their exact time of impact; the rest of
  /// the step's contacts are resolved at the end of the step.
  int max_impacts_per_step = 16;
  /// m: overlap left in resting contacts so that they keep touching; a stack of n boxes sinks by
  /// about n times this.
  double linear_slop = 2e-4;
  double contact_margin = 0.02;  ///< m: shapes this close get (speculative) contact points
  /// Islands at rest stop costing: an island of touching dynamic bodies whose every body has
  /// moved slower than sleep_speed and sleep_angular_speed for time_to_sleep is held still and
  /// skipped until something touches it, an edit or a force reaches it, or a kinematic body
  /// moves into it. Off by default: a verification scene integrates every body at every step.
  bool sleep = false;
  double sleep_speed = 0.01;           ///< m/s (Box2D 2.4's b2_linearSleepTolerance)
  double sleep_angular_speed = 0.035;  ///< rad/s (2°/s)
  double time_to_sleep = 0.5;          ///< s (Box2D's b2_timeToSleep)
  /// Islands of more than this many contacts are solved colour by colour (a graph colouring: no
  /// two contacts of a colour share a moving body), so that threads share one island; 0: never.
  /// Off by default: in the colours' order a 100-row pyramid sways 1.4 m sideways in 500 steps,
  /// against 0.29 m in the contacts' own order. The same on any number of threads either way.
  int coloured_island_contacts = 0;
  /// Islands of more than this many contacts are cut into island_parts parts, by halving them
  /// where the cut is shorter, so that threads share them: the parts are solved side by side,
  /// each in the contacts' order, then the contacts between them. 0: never. The same on any
  /// number of threads either way.
  int island_part_contacts = 4096;
  /// The most parts island_parts may ask for: six halvings.
  static constexpr int kMaxIslandParts = 64;
  /// Into how many parts such an island is cut: a power of two from 2 to kMaxIslandParts. Two, one
  /// per core of the machines the bench runs on: each further halving costs the preparation a pass
  /// over the island and makes the parts' levels shorter (rain16000 on one thread: 16 parts, 11%
  /// slower).
  int island_parts = 2;
  /// Sets of one-point contacts of more than this many are stored, for the solver's stages, in
  /// the order the passes solve them (ContactBatches::store_in_order), with the same result to
  /// the bit. Not read from scenes: it changes speed alone. Moving a set there and back costs
  /// more than the passes gain by it until the set is several times a core's 1 MiB L2 cache
  /// (about 130 B a contact and 40 B a body): stored, rain4000's 9,400 contacts took 2.5% longer
  /// on one thread and rain16000's 36,400 3.4% shorter.
  int stored_in_order_contacts = 16384;
};

}  // namespace gp
