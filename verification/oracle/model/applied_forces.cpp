#include "verification/oracle/model/applied_forces.hpp"

#include "gamephysics/models/dd/torque.hpp"
#include "gamephysics/models/gd/gravitational_acceleration.hpp"
#include "gamephysics/models/im/rotational_motion.hpp"
#include "gamephysics/models/im/translational_motion.hpp"
#include "verification/oracle/model/rotation.hpp"

namespace gp::oracle {

namespace {

bool dynamic(const RigidBody& body) {
  return body.type == BodyType::Dynamic;
}

/// g at body j [m/s²]: uniform gravity plus the pull of every other dynamic body.
Vec2 gravity_at(const World& world, std::span<const Motion> motion, std::size_t j) {
  Vec2 g = world.gravity;
  if (!world.G) return g;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    if (i == j || !dynamic(world.bodies[i])) continue;
    g += gd::gravitational_acceleration(*world.G, world.bodies[i].mass,
                                        motion[j].position - motion[i].position);
  }
  return g;
}

}  // namespace

void applied_accelerations(const World& world, std::span<const Motion> motion,
                           std::span<Vec2> linear, std::span<double> angular) {
  for (std::size_t j = 0; j < world.bodies.size(); ++j) {
    const RigidBody& body = world.bodies[j];
    linear[j] = Vec2::Zero();
    angular[j] = 0.0;
    if (!dynamic(body)) continue;
    linear[j] = im::translational_acceleration(gravity_at(world, motion, j), body.force, body.mass);
    if (body.inverse_moment == 0.0) continue;
    double torque = body.torque;
    // The point of application turns with the body.
    if (body.force_arm) torque += dd::torque(rotated(*body.force_arm, motion[j].angle), body.force);
    angular[j] = im::angular_acceleration(torque, body.moment);
  }
}

}  // namespace gp::oracle
