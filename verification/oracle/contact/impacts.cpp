#include "verification/oracle/contact/impacts.hpp"

#include <stdexcept>

#include "gamephysics/models/im/collision_response.hpp"
#include "verification/oracle/contact/body_coupling.hpp"
#include "verification/oracle/contact/lemke.hpp"

namespace gp::oracle {

namespace {

double restitution_of(const ActiveContact& c, const ContactKinematics& k, double rest_speed) {
  return k.gap_rate < -rest_speed ? c.restitution : 0.0;
}

// IM:col2D, the SRS's own model, for a contact that is alone.
double resolve_one(const World& world, const ActiveContact& c, const ContactKinematics& k,
                   double restitution, std::span<Vec2> velocity,
                   std::span<double> angular_velocity) {
  const RigidBody& first = world.bodies[c.first];
  const RigidBody& second = world.bodies[c.second];
  const im::CollisionResponse r =
      im::collision_response({first.inverse_mass, first.inverse_moment, velocity[c.first],
                              angular_velocity[c.first], k.first_arm},
                             {second.inverse_mass, second.inverse_moment, velocity[c.second],
                              angular_velocity[c.second], k.second_arm},
                             k.normal, restitution);
  velocity[c.first] = r.velocity_a;
  angular_velocity[c.first] = r.angular_velocity_a;
  velocity[c.second] = r.velocity_b;
  angular_velocity[c.second] = r.angular_velocity_b;
  return r.impulse;
}

}  // namespace

std::vector<double> resolve_impacts(const World& world, std::span<const ActiveContact> contacts,
                                    std::span<const ContactKinematics> kinematics,
                                    double rest_speed, std::span<Vec2> velocity,
                                    std::span<double> angular_velocity) {
  const auto n = static_cast<Eigen::Index>(contacts.size());
  if (n == 1) {
    return {resolve_one(world, contacts[0], kinematics[0],
                        restitution_of(contacts[0], kinematics[0], rest_speed), velocity,
                        angular_velocity)};
  }
  std::vector<BodyPairVector> normal;
  for (Eigen::Index i = 0; i < n; ++i)
    normal.push_back(along(contacts[i], kinematics[i].normal_row));
  Eigen::MatrixXd G(n, n);
  Eigen::VectorXd q(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double arrival = dot(normal[i], velocity, angular_velocity);
    q[i] = (1.0 + restitution_of(contacts[i], kinematics[i], rest_speed)) * arrival;
    for (Eigen::Index k = 0; k < n; ++k) G(i, k) = coupling(world, normal[i], normal[k]);
  }
  const auto p = solve_lcp(G, q);
  if (!p) throw std::runtime_error("oracle: no impulses satisfy Newton's law at the contacts");
  for (Eigen::Index i = 0; i < n; ++i) {
    add_response(world, normal[i], (*p)[i], velocity, angular_velocity);
  }
  return {p->begin(), p->end()};
}

}  // namespace gp::oracle
