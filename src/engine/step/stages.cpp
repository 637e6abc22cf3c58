#include "engine/step/stages.hpp"

#include <array>
#include <sstream>
#include <string>

#include "engine/collision/hull.hpp"
#include "engine/solver/single_point_lanes.hpp"
#include "engine/solver/velocity_passes.hpp"
#include "gamephysics/models/dd/angular_displacement.hpp"
#include "gamephysics/models/dd/angular_velocity.hpp"
#include "gamephysics/models/dd/linear_displacement.hpp"
#include "gamephysics/models/dd/linear_velocity.hpp"

namespace gp {

namespace {

bool collides(const StepContext& c) {
  return c.collides;
}
// Contacts bounce only where a shape's restitution is above 0 (the larger of the two counts).
bool bounces(const StepContext& c) {
  return c.collides && c.shapes.any_bounce();
}
bool solves_islands(const StepContext& c) {
  return c.collides && c.settings.direct_solve_points > 0;
}
bool has_dynamic(const StepContext& c) {
  return !c.forces.bodies().empty();
}
bool sleeps(const StepContext& c) {
  return c.settings.sleep;
}
bool sleeps_in_piles(const StepContext& c) {
  return c.settings.sleep && c.collides;
}
bool has_kinematic(const StepContext& c) {
  return !c.kinematic.empty();
}

std::string count(std::size_t n, const std::string& what) {
  return std::to_string(n) + " " + what;
}

// The ballistic paths over the sub-step under the accelerations at its start, the shapes placed at
// their start, their boxes at their end, and the candidate pairs of the boxes swept between.
bool sweep(StepContext& c, StepMechanisms& m) {
  const PathShape shape = c.integrator->path_under_constant_acceleration();
  const bool constant = c.forces.constant();
  if (constant) {
    c.motion.emplace(c.start, StepAccelerations(c.forces, c.dynamic), shape, c.h);
  } else {
    c.varying_acceleration.resize(c.state.position.size());
    c.forces.evaluate(c.time, c.start, c.varying_acceleration);
    c.motion.emplace(c.start, StepAccelerations(c.varying_acceleration), shape, c.h);
  }
  // A body that slept when its shapes were last placed has not moved since: they stay where
  // they are. Its path is still too under constant forces, where a sleeping body has no
  // acceleration; evaluated forces may give it one.
  const auto unmoved = [&c](BodyId b) { return placed_asleep(c, b); };
  const auto unmoved_path = [&c, constant](BodyId b) { return constant && placed_asleep(c, b); };
  c.shapes.place(c.start.position, c.start.angle, c.world_start, unmoved);
  // Boxes swept along the ballistic path catch a fast body wherever it is during the step. The
  // path covers every body: kinematic and static ones have no acceleration, so it ends where
  // the kinematic stage moves them, and static ones where they are.
  const Ballistic& path = *c.motion;
  const double h = c.h;
  c.shapes.bound_moved(c.world_start, c.start.position, path, h, c.end_bounds, unmoved_path);
  note_placed_asleep(c);
  c.pairs = m.detection.candidate_pairs(c.shapes, c.dynamic, c.world_start, c.end_bounds);
  return true;
}

// A sleeping island that something reaches wakes before the contacts are found; the pairs are
// found again with its bodies awake.
bool wake(StepContext& c, StepMechanisms& m) {
  if (wake_touched(c)) sweep(c, m);
  return true;
}

bool hold(StepContext& c, StepMechanisms&) {
  hold_sleeping(c);
  return true;
}

bool fall_asleep(StepContext& c, StepMechanisms& m) {
  gp::fall_asleep(c, m.sleep);
  return true;
}

// Shortens the sub-step to the earliest impact; its pairs leave the contacts' pairs, as they are
// resolved exactly at t_c and the solver must not close their gap before.
bool search_impacts(StepContext& c, StepMechanisms& m) {
  if (!c.impacts_allowed()) return true;
  const auto tau = m.impact_search.earliest(c);
  if (!tau || *tau >= c.h) return true;
  c.h = *tau;
  c.impact_pairs = m.impact_search.touching();
  c.pairs = m.detection.drop_pairs(c.impact_pairs);
  return true;
}

bool find_contacts(StepContext& c, StepMechanisms& m) {
  m.detection.find_contacts(c);
  return true;
}

bool resolve_local_impacts(StepContext& c, StepMechanisms& m) {
  m.local_impacts.classify(c);
  m.local_impacts.hand_over(c);
  if (!m.local_impacts.resolve(c)) return false;
  c.state = c.start;
  return true;
}

// Impacts among touching bodies happen at the start of the step, before its forces.
bool propagate(StepContext& c, StepMechanisms&) {
  if (!c.contacts.empty() &&
      propagate_impacts(c.contacts, c.shapes, c.inertia, c.settings, c.state)) {
    c.start.velocity = c.state.velocity;
    c.start.angular_velocity = c.state.angular_velocity;
  }
  return true;
}

bool integrate(StepContext& c, StepMechanisms&) {
  c.integrator->advance(c.forces, c.time, c.h, c.state);
  return true;
}

bool move_kinematic(StepContext& c, StepMechanisms&) {
  for (BodyId k : c.kinematic) {
    c.state.position[k] = dd::displaced_position(
        c.state.position[k], dd::displacement_from_velocity(c.state.velocity[k], c.h));
    c.state.angle[k] = dd::rotated_orientation(
        c.state.angle[k], dd::angular_displacement_from_velocity(c.state.angular_velocity[k], c.h));
  }
  return true;
}

// A solver stage runs only while there are contacts to solve.
template <void (ContactSolver::*Solve)(StepContext&)>
bool on_contacts(StepContext& c, StepMechanisms& m) {
  if (!c.contacts.empty()) (m.solver.*Solve)(c);
  return true;
}

bool solve_speculative(StepContext& c, StepMechanisms& m) {
  if (!c.speculative_contacts.empty()) m.solver.solve_speculative(c);
  return true;
}

bool keep_warm_starts(StepContext& c, StepMechanisms& m) {
  m.solver.restore_order(c);
  keep_impulses(c.contacts, c.warm_starts);
  return true;
}

// The impacts that ended the sub-step, resolved at its end, t_c.
bool resolve_sub_step_impacts(StepContext& c, StepMechanisms& m) {
  if (c.impact_pairs.empty()) return true;
  resolve_impacts(c.impact_pairs, c, c.time + c.h, c.state, m.impact_contacts);
  ++c.impacts_this_step;
  return true;
}

std::string describe_integration(const StepContext& c) {
  const auto rotating =
      static_cast<std::size_t>(std::count(c.forces.rotates().begin(), c.forces.rotates().end(), 1));
  // A stream rather than string concatenation, which gcc 12 at -O3 flags with a false
  // -Warray-bounds once Eigen's header is precompiled.
  std::ostringstream text;
  text << count(c.forces.bodies().size(), "dynamic bodies, ") << rotating
       << " of them rotating (the others skip rotation)";
  if (c.settings.gravity != Vec2::Zero()) text << "; uniform gravity g (IM:transMot)";
  if (c.settings.G) {
    text << "; pairwise gravitation G m / d², O(N²) (TM:UniversalGravLaw GD:accelGravity)";
  }
  if (c.forces.any_applied()) {
    text << "; applied forces and torques, constant, at a point or time-dependent "
            "(TM:NewtonSecLawMot TM:NewtonSecLawRotMot DD:torque)";
  }
  return text.str();
}

constexpr std::array kStages{
    Stage{"broadphase: sweep and prune", "FR:Determine-Collisions", kLocalPass | kSubStepPass,
          collides,
          [](const StepContext& c) {
            return count(c.shapes.size(), "shapes, boxes swept along the ballistic paths");
          },
          sweep},
    Stage{"sleep: islands reached wake up", "", kLocalPass | kSubStepPass, sleeps_in_piles,
          [](const StepContext&) {
            return std::string(
                "a sleeping island paired with an awake body, or in a moving "
                "kinematic body's swept box, wakes before the contacts are found");
          },
          wake},
    Stage{"time of impact: sub-step ends at the first impact", "IM:col2D", kSubStepPass, collides,
          [](const StepContext&) {
            return std::string("the sub-step is shortened to the earliest impact of any pair");
          },
          search_impacts},
    Stage{"narrowphase: contact manifolds",
          "FR:Determine-Collisions A:collisionType LC:Expanded-Collisions",
          kLocalPass | kSubStepPass, collides,
          [](const StepContext&) {
            return std::string(
                       "1 point (vertex to edge) or 2 points (edge to edge), warm started; a box "
                       "against a box takes ") +
                   box_lanes_name(widest_lanes());
          },
          find_contacts},
    Stage{"time of impact: local impacts", "IM:col2D GD:impulse", kLocalPass, collides,
          [](const StepContext&) {
            return std::string(
                "impacts resolved at t_c for their own bodies; impacts on resting "
                "bodies handed to the solver as speculative contacts");
          },
          resolve_local_impacts},
    Stage{"impacts among touching bodies", "IM:col2D", kLocalPass | kSubStepPass, bounces,
          [](const StepContext&) {
            return std::string("resting bodies struck, pair after pair (a Newton's cradle)");
          },
          propagate},
    Stage{"integration",
          "IM:transMot IM:rotMot DD:linAcc DD:linVel DD:linDisp DD:angAccel "
          "DD:angVel DD:angDisp FR:Calculate-Translation-Over-Time "
          "FR:Calculate-Rotation-Over-Time",
          kLocalPass | kSubStepPass, has_dynamic, describe_integration, integrate},
    Stage{"kinematic bodies", "DD:linVel DD:angVel", kLocalPass | kSubStepPass, has_kinematic,
          [](const StepContext& c) {
            return count(c.kinematic.size(), "bodies moved at their velocity");
          },
          move_kinematic},
    Stage{"sleep: sleeping bodies held", "", kLocalPass | kSubStepPass, sleeps,
          [](const StepContext&) {
            return std::string("sleeping bodies stay where they fell asleep, at rest");
          },
          hold},
    Stage{"contact solver: prepare and warm start", "GD:impulse DD:impulseV",
          kLocalPass | kSubStepPass, collides,
          [](const StepContext& c) {
            return "the order of solving, in which a set of more than " +
                   std::to_string(c.settings.stored_in_order_contacts) +
                   " one-point contacts is stored; effective masses, targets and bounces; last "
                   "impulses carried over";
          },
          on_contacts<&ContactSolver::prepare>},
    Stage{"contact solver: islands solved directly",
          "FR:Determine-Collision-Response-Over-Time GD:impulse DD:impulseV TM:NewtonThirdLawMot",
          kLocalPass | kSubStepPass, solves_islands,
          [](const StepContext& c) {
            std::ostringstream text;
            text << "normal impulses of islands of at most " << c.settings.direct_solve_points
                 << " points, or " << c.settings.direct_solve_uneven_points
                 << " where masses differ more than " << c.settings.direct_solve_mass_ratio
                 << "-fold, all at once (active set); resting islands surveyed unless every body "
                    "is too slow to be unheld";
            return text.str();
          },
          on_contacts<&ContactSolver::solve_small_islands>},
    Stage{"contact solver: sequential impulses",
          "FR:Determine-Collision-Response-Over-Time GD:impulse DD:reVeInColl DD:chaslesThm "
          "DD:impulseV TM:NewtonThirdLawMot",
          kLocalPass | kSubStepPass, collides,
          [](const StepContext& c) {
            std::string text =
                "resting and persistent contacts; at most " +
                std::to_string(c.settings.velocity_iterations) +
                " passes, ending once a pass changes no velocity by more than the "
                "tolerance; islands of one-point contacts by levels of contacts that "
                "share no body, their contacts " +
                contact_lanes_name();
            if (c.settings.coloured_island_contacts > 0) {
              text += "; coloured islands by colour, their one-point and two-point contacts " +
                      std::string(contact_lanes_name());
            }
            return text;
          },
          on_contacts<&ContactSolver::solve_velocities>},
    Stage{"contact solver: restitution", "IM:col2D", kLocalPass | kSubStepPass, bounces,
          [](const StepContext&) {
            return std::string("the bounce of approaching points, in one pass after the others");
          },
          on_contacts<&ContactSolver::apply_restitution>},
    Stage{"contact solver: impulses move the bodies", "DD:impulseV DD:torque",
          kLocalPass | kSubStepPass, collides,
          [](const StepContext&) {
            return std::string("positions moved by the impulses' velocity changes over the step");
          },
          on_contacts<&ContactSolver::move_by_impulses>},
    Stage{"speculative contacts", "IM:col2D GD:impulse", kLocalPass | kSubStepPass, collides,
          [](const StepContext&) {
            return std::string("impacts on resting bodies, solved with the contacts near them");
          },
          solve_speculative},
    Stage{"position correction", "FR:Determine-Collision-Response-Over-Time",
          kLocalPass | kSubStepPass, collides,
          [](const StepContext&) {
            return std::string(
                "overlap removed by moving positions only; none at a step whose bodies moved too "
                "little for any point to pass the slop");
          },
          on_contacts<&ContactSolver::correct_positions>},
    Stage{"warm starts kept", "", kLocalPass | kSubStepPass, collides,
          [](const StepContext&) {
            return std::string(
                "contacts stored in the order of solving put back in their own; each point's "
                "impulses, for the next sub-step");
          },
          keep_warm_starts},
    Stage{"sleep: islands at rest fall asleep", "", kLocalPass | kSubStepPass, sleeps_in_piles,
          [](const StepContext& c) {
            return "islands whose bodies all moved slower than " +
                   std::to_string(c.settings.sleep_speed) + " m/s and " +
                   std::to_string(c.settings.sleep_angular_speed) + " rad/s for " +
                   std::to_string(c.settings.time_to_sleep) +
                   " s; once every body sleeps and "
                   "nothing moves, a step runs no stage and advances the clock alone";
          },
          fall_asleep},
    Stage{"impacts at the end of the sub-step", "IM:col2D GD:impulse", kSubStepPass, collides,
          [](const StepContext&) {
            return std::string("IM:col2D at t_c for one point, else an iterated solve");
          },
          resolve_sub_step_impacts},
};

}  // namespace

std::span<const Stage> step_stages() {
  return kStages;
}

bool runs_local_pass(const StepContext& c) {
  // Local impacts need paths that the integrator follows exactly: each integrator does, under
  // constant forces (PathShape).
  return c.collides && c.forces.constant();
}

}  // namespace gp
