// Space::pipeline(): the stages a step runs for this space, for `simulate --explain`.
#include <algorithm>

#include "engine/space.hpp"

namespace gp {

std::vector<PipelineStage> Space::pipeline() const {
  std::vector<PipelineStage> stages;
  const auto& dynamic = forces_.bodies();
  const std::size_t rotating = std::count(forces_.rotates().begin(), forces_.rotates().end(), 1);
  const std::size_t statics = std::count(types_.begin(), types_.end(), BodyType::Static);
  const std::string n = std::to_string(dynamic.size()) + " dynamic bodies";
  if (settings_.gravity != Vec2::Zero()) {
    stages.push_back({"uniform gravity", "IM:transMot", "g added to every dynamic body"});
  }
  if (settings_.G) {
    stages.push_back({"pairwise gravitation", "TM:UniversalGravLaw GD:accelGravity",
                      "G m / d² between all " + n + " (O(N²))"});
  }
  if (forces_.any_applied()) {
    stages.push_back({"applied forces and torques",
                      "TM:NewtonSecLawMot TM:NewtonSecLawRotMot DD:torque",
                      "constant, at-a-point and time-dependent forces"});
  }
  if (!dynamic.empty()) {
    stages.push_back(
        {"translation: " + std::string(integrator_name(settings_.integrator)),
         "IM:transMot DD:linAcc DD:linVel DD:linDisp FR:Calculate-Translation-Over-Time",
         "positions and velocities of " + n});
  }
  if (rotating > 0) {
    stages.push_back({"rotation: " + std::string(integrator_name(settings_.integrator)),
                      "IM:rotMot DD:angAccel DD:angVel DD:angDisp FR:Calculate-Rotation-Over-Time",
                      "orientations of " + std::to_string(rotating) +
                          " bodies that can rotate (the others are skipped)"});
  }
  if (!kinematic_.empty()) {
    stages.push_back({"kinematic bodies", "DD:linVel DD:angVel",
                      std::to_string(kinematic_.size()) + " bodies moved at their velocity"});
  }
  if (collides_) {
    stages.push_back({"broadphase: sweep and prune", "FR:Determine-Collisions",
                      std::to_string(shapes_.size()) + " shapes, boxes swept over the step"});
    stages.push_back({"narrowphase: contact manifolds",
                      "FR:Determine-Collisions A:collisionType LC:Expanded-Collisions",
                      "1 point (vertex to edge) or 2 points (edge to edge)"});
    const bool local = forces_.constant() && integrator_->exact_for_constant_acceleration();
    stages.push_back({"time of impact", "IM:col2D GD:impulse",
                      local ? "impacts resolved at t_c for their own bodies; impacts on resting "
                              "bodies as speculative contacts"
                            : "each impact ends a sub-step of the whole space (forces or "
                              "integrator not exact along ballistic paths)"});
    if (settings_.direct_solve_points > 0) {
      stages.push_back({"contact solver: small islands solved directly",
                        "FR:Determine-Collision-Response-Over-Time GD:impulse DD:impulseV "
                        "TM:NewtonThirdLawMot",
                        "normal impulses of islands of at most " +
                            std::to_string(settings_.direct_solve_points) +
                            " points, all at once (active set)"});
    }
    stages.push_back({"contact solver: sequential impulses",
                      "FR:Determine-Collision-Response-Over-Time GD:impulse DD:reVeInColl "
                      "DD:chaslesThm DD:impulseV TM:NewtonThirdLawMot",
                      "resting and persistent contacts, warm started; at most " +
                          std::to_string(settings_.velocity_iterations) +
                          " passes, ending once a pass changes no velocity by more than the "
                          "tolerance"});
    stages.push_back({"position correction", "FR:Determine-Collision-Response-Over-Time",
                      "overlap removed by moving positions only"});
  } else {
    stages.push_back({"collisions: skipped", "FR:Determine-Collisions",
                      "no two shapes of different bodies can touch"});
  }
  if (statics > 0) {
    stages.push_back({"static bodies", "", std::to_string(statics) + " bodies: no work per step"});
  }
  return stages;
}

}  // namespace gp
