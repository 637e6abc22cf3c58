#include "verification/oracle/stepping/moreau_jean.hpp"

#include <algorithm>
#include <numeric>
#include <vector>

#include "verification/oracle/contact/impacts.hpp"
#include "verification/oracle/model/applied_forces.hpp"

namespace gp::oracle {

namespace {

// The clusters of contacts: contacts sharing a dynamic body, transitively (union–find on bodies).
std::vector<std::vector<std::size_t>> clusters(const World& world,
                                               std::span<const StepContact> contacts) {
  std::vector<std::size_t> parent(world.bodies.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto root = [&](std::size_t b) {
    while (parent[b] != b) b = parent[b] = parent[parent[b]];
    return b;
  };
  const auto dynamic = [&](std::size_t b) { return world.bodies[b].type == BodyType::Dynamic; };
  for (const StepContact& s : contacts) {
    if (dynamic(s.contact.first) && dynamic(s.contact.second)) {
      parent[root(s.contact.first)] = root(s.contact.second);
    }
  }
  std::vector<std::vector<std::size_t>> by_root(world.bodies.size());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const std::size_t body =
        dynamic(contacts[i].contact.first) ? contacts[i].contact.first : contacts[i].contact.second;
    by_root[root(body)].push_back(i);
  }
  std::erase_if(by_root, [](const auto& c) { return c.empty(); });
  return by_root;
}

}  // namespace

void moreau_jean_step(const World& world, std::span<const StepContact> contacts, double h,
                      std::span<Motion> motions) {
  const std::size_t n = world.bodies.size();
  std::vector<Vec2> linear(n);
  std::vector<double> angular(n);
  applied_accelerations(world, motions, linear, angular);
  std::vector<Vec2> velocity(n);
  std::vector<double> angular_velocity(n);
  for (std::size_t b = 0; b < n; ++b) {
    velocity[b] = motions[b].velocity + h * linear[b];
    angular_velocity[b] = motions[b].angular_velocity + h * angular[b];
  }
  for (const std::vector<std::size_t>& cluster : clusters(world, contacts)) {
    std::vector<FrictionRow> rows;
    for (std::size_t i : cluster) {
      const ActiveContact& c = contacts[i].contact;
      const ContactKinematics& k = contacts[i].kinematics;
      const BodyPairVector normal = along(c, k.normal_row);
      const BodyPairVector tangent = along(c, k.tangent_row);
      // Newton's law on the step: only an arrival bounces; a pair already parting may not be
      // sent back by its own rate.
      rows.push_back(
          {normal, normal, tangent,
           dot(normal, velocity, angular_velocity) + c.restitution * std::min(k.gap_rate, 0.0),
           dot(tangent, velocity, angular_velocity), c.friction, c.friction > 0.0});
    }
    solve_impulses(world, rows, velocity, angular_velocity);
  }
  for (std::size_t b = 0; b < n; ++b) {
    Motion& m = motions[b];
    m.position += 0.5 * h * (m.velocity + velocity[b]);
    m.angle += 0.5 * h * (m.angular_velocity + angular_velocity[b]);
    m.velocity = velocity[b];
    m.angular_velocity = angular_velocity[b];
  }
}

}  // namespace gp::oracle
