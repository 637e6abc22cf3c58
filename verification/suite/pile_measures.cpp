#include "verification/suite/pile_measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/scene/scene_space.hpp"

namespace gp::verification {

PileMeasures measure_pile(const Scene& scene, const Trajectory& run) {
  const auto space = build_space(scene);
  PileMeasures m;
  const Vec2 g = scene.settings.gravity;
  std::vector<double> kinetic;
  for (const std::vector<BodyState>& states : run.states) {
    double potential = 0.0;
    double moving = 0.0;
    for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
      if (scene.bodies[b].type != BodyType::Dynamic) continue;
      const auto id = static_cast<BodyId>(b);
      const BodyState& s = states[b];
      moving += 0.5 * space->mass(id) * s.velocity.squaredNorm() +
                0.5 * space->moment(id) * s.angular_velocity * s.angular_velocity;
      potential -= space->mass(id) * g.dot(s.position);
    }
    m.energy.push_back(moving + potential);
    kinetic.push_back(moving);
  }
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    if (scene.bodies[b].type != BodyType::Dynamic) continue;
    lowest = std::min(lowest, run.states.front()[b].position.y());
    m.profile.push_back(run.states.back()[b].position.y());
  }
  std::sort(m.profile.begin(), m.profile.end());
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    if (scene.bodies[b].type != BodyType::Dynamic) continue;
    m.drop += space->mass(static_cast<BodyId>(b)) * g.norm() *
              (run.states.front()[b].position.y() - lowest);
  }
  std::size_t settled = kinetic.size();
  while (settled > 0 && kinetic[settled - 1] < kSettledShare * m.drop) --settled;
  m.settle_time = run.times[std::min(settled, run.times.size() - 1)];
  return m;
}

PileDifferences pile_differences(const PileMeasures& a, const PileMeasures& reference) {
  PileDifferences d;
  const double drop = std::max(reference.drop, 1e-12);
  for (std::size_t k = 0; k < a.energy.size(); ++k) {
    d.energy = std::max(d.energy, std::abs(a.energy[k] - reference.energy[k]) / drop);
  }
  d.settled_energy = std::abs(a.energy.back() - reference.energy.back()) / drop;
  d.settle_time = std::abs(a.settle_time - reference.settle_time);
  for (std::size_t i = 0; i < a.profile.size(); ++i) {
    d.profile = std::max(d.profile, std::abs(a.profile[i] - reference.profile[i]));
  }
  return d;
}

}  // namespace gp::verification
