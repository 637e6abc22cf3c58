#include "verification/quantities/mechanical_quantities.hpp"

#include <cmath>
#include <vector>

#include "gamephysics/models/dd/kinetic_energy.hpp"
#include "gamephysics/models/dd/potential_energy.hpp"

namespace gp::verification {

BodyQuantities body_quantities(const Space& space, BodyId body) {
  BodyQuantities q;
  if (space.type(body) != BodyType::Dynamic) return q;
  const BodyState s = space.state(body);
  const double m = space.mass(body);
  // A body that cannot rotate has an infinite moment and ω = 0: no rotational share.
  const double I = std::isinf(space.moment(body)) ? 0.0 : space.moment(body);
  q.translational_energy = dd::kinetic_energy(m, s.velocity, 0.0, 0.0);
  q.rotational_energy = dd::kinetic_energy(0.0, Vec2::Zero(), I, s.angular_velocity);
  q.potential_energy = dd::potential_energy(m, space.settings().gravity, s.position);
  q.momentum = m * s.velocity;
  q.angular_momentum = m * cross(s.position, s.velocity) + I * s.angular_velocity;
  return q;
}

Invariants invariants(const Space& space) {
  Invariants v;
  std::vector<BodyId> dynamic;
  for (BodyId id = 0; id < space.body_count(); ++id) {
    if (space.type(id) != BodyType::Dynamic) continue;
    dynamic.push_back(id);
    const BodyQuantities q = body_quantities(space, id);
    v.translational_energy += q.translational_energy;
    v.rotational_energy += q.rotational_energy;
    v.potential_energy += q.potential_energy;
    v.momentum += q.momentum;
    v.angular_momentum += q.angular_momentum;
  }
  if (const auto G = space.settings().G) {
    // The pairwise potential −G m_i m_j / d, whose gradient is TM:UniversalGravLaw (the SRS has
    // no DD for it: DD:potEnergy is the uniform field).
    for (std::size_t i = 0; i < dynamic.size(); ++i) {
      for (std::size_t j = i + 1; j < dynamic.size(); ++j) {
        const double d =
            (space.state(dynamic[i]).position - space.state(dynamic[j]).position).norm();
        v.potential_energy -= *G * space.mass(dynamic[i]) * space.mass(dynamic[j]) / d;
      }
    }
  }
  return v;
}

}  // namespace gp::verification
