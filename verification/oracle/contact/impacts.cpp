#include "verification/oracle/contact/impacts.hpp"

#include <stdexcept>

#include "gamephysics/models/im/collision_response.hpp"
#include "verification/oracle/contact/friction_lcp.hpp"
#include "verification/oracle/contact/lemke.hpp"

namespace gp::oracle {

namespace {

constexpr double kRegularisation = 1e-14;

double restitution_of(const ActiveContact& c, const ContactKinematics& k, double rest_speed) {
  return k.gap_rate < -rest_speed ? c.restitution : 0.0;
}

// IM:col2D, the SRS's own model, for a frictionless contact that is alone.
Impulse resolve_one(const World& world, const ActiveContact& c, const ContactKinematics& k,
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
  return {r.impulse, 0.0};
}

}  // namespace

std::vector<Impulse> solve_impulses(const World& world, std::span<const FrictionRow> rows,
                                    std::span<Vec2> velocity, std::span<double> angular_velocity) {
  FrictionLcp lcp = friction_lcp(world, rows);
  auto z = solve_lcp(lcp.M, lcp.q);
  if (!z) {
    // The problem has a solution (its matrix is copositive, and q is of Anitescu and Potra's
    // form), but degenerate ones (a pile: dozens of contacts, most at rest) can end Lemke's method
    // on a ray by round-off. M + εI is strictly copositive, which it always solves; ε = 1e-14 of
    // the largest diagonal entry moves the impulses by about that share of themselves.
    lcp.M.diagonal().array() += kRegularisation * lcp.M.diagonal().cwiseAbs().maxCoeff();
    z = solve_lcp(lcp.M, lcp.q);
  }
  if (!z) throw std::runtime_error("no impulses satisfy Newton's and Coulomb's laws");
  for (Eigen::Index k = 0; k < z->size(); ++k) {
    add_response(world, lcp.push[static_cast<std::size_t>(k)], (*z)[k], velocity, angular_velocity);
  }
  std::vector<Impulse> impulses;
  for (const FrictionSlots& s : lcp.slots) {
    impulses.push_back({(*z)[s.normal], s.plus < 0 ? 0.0 : (*z)[s.plus] - (*z)[s.plus + 1]});
  }
  return impulses;
}

std::vector<Impulse> resolve_impacts(const World& world, std::span<const ActiveContact> contacts,
                                     std::span<const ContactKinematics> kinematics,
                                     double rest_speed, std::span<Vec2> velocity,
                                     std::span<double> angular_velocity) {
  const std::size_t n = contacts.size();
  if (n == 1 && contacts[0].friction == 0.0) {
    return {resolve_one(world, contacts[0], kinematics[0],
                        restitution_of(contacts[0], kinematics[0], rest_speed), velocity,
                        angular_velocity)};
  }
  std::vector<FrictionRow> rows;
  for (std::size_t i = 0; i < n; ++i) {
    const ActiveContact& c = contacts[i];
    const BodyPairVector normal = along(c, kinematics[i].normal_row);
    const BodyPairVector tangent = along(c, kinematics[i].tangent_row);
    const double arrival = dot(normal, velocity, angular_velocity);
    rows.push_back({normal, normal, tangent,
                    (1.0 + restitution_of(c, kinematics[i], rest_speed)) * arrival,
                    dot(tangent, velocity, angular_velocity), c.friction, c.friction > 0.0});
  }
  return solve_impulses(world, rows, velocity, angular_velocity);
}

}  // namespace gp::oracle
