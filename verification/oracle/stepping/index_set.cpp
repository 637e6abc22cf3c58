#include "verification/oracle/stepping/index_set.hpp"

#include <cmath>
#include <limits>

#include "verification/oracle/geometry/contact_geometry.hpp"
#include "verification/oracle/geometry/placement.hpp"

namespace gp::oracle {

std::vector<StepContact> index_set(const World& world, std::span<const HullPair> pairs,
                                   std::span<const Motion> motions, double h, double tolerance) {
  std::vector<StepContact> contacts;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const HullPair& pair = pairs[p];
    const Motion& a = motions[pair.body_a];
    const Motion& b = motions[pair.body_b];
    const Hull& ha = world.bodies[pair.body_a].hulls[pair.hull_a];
    const Hull& hb = world.bodies[pair.body_b].hulls[pair.hull_b];
    // The gap is at least the distance of the centres less both reaches, and closes at most at
    // the two bodies' fastest points' speed: a pair that cannot close in half a step is skipped.
    const double ra = reach(ha), rb = reach(hb);
    const double speed = a.velocity.norm() + b.velocity.norm() + std::abs(a.angular_velocity) * ra +
                         std::abs(b.angular_velocity) * rb;
    if ((a.position - b.position).norm() - ra - rb > 0.5 * h * speed + tolerance) continue;
    // Every nearest feature pair (an unbounded margin): whether it closes within the step is
    // decided below, on its rate, not on a fixed distance.
    const ContactGeometry geometry =
        contact_geometry(ha, {a.position, a.angle}, hb, {b.position, b.angle},
                         std::numeric_limits<double>::infinity());
    for (const ContactPoint& point : geometry.points) {
      ActiveContact c = make_active_contact(world, pair, p, point.feature);
      ContactKinematics k = contact_kinematics(c, motions[c.first], motions[c.second]);
      if (k.gap + 0.5 * h * k.gap_rate <= tolerance) contacts.push_back({c, k});
    }
  }
  return contacts;
}

}  // namespace gp::oracle
