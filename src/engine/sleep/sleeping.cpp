#include "engine/sleep/sleeping.hpp"

#include <algorithm>
#include <numeric>

#include "engine/solver/contact_islands.hpp"

namespace gp {

namespace {

// Whether kinematic body `k` moves, and so may reach a sleeping island.
bool kinematic_moves(const StepContext& c, BodyId k) {
  return c.state.velocity[k] != Vec2::Zero() || c.state.angular_velocity[k] != 0.0;
}

}  // namespace

void note_placed_asleep(StepContext& c) {
  if (c.placed_asleep.empty()) return;
  for (BodyId j : c.forces.bodies()) c.placed_asleep[j] = asleep(c, j) ? 1 : 0;
}

bool stands_still(const StepContext& c) {
  if (c.sleep_island.empty() || !c.contacts.empty() || !c.warm_starts.empty()) return false;
  if (std::any_of(c.kinematic.begin(), c.kinematic.end(),
                  [&c](BodyId k) { return kinematic_moves(c, k); })) {
    return false;
  }
  const std::vector<BodyId>& bodies = c.forces.bodies();
  return std::all_of(bodies.begin(), bodies.end(), [&c](BodyId j) { return asleep(c, j); });
}

void wake_island(StepContext& c, BodyId body) {
  if (!asleep(c, body)) return;
  const std::uint32_t island = c.sleep_island[body];
  for (BodyId j = 0; j < c.sleep_island.size(); ++j) {
    if (c.sleep_island[j] != island) continue;
    c.sleep_island[j] = kAwake;
    c.placed_asleep[j] = 0;
    c.dynamic[j] = 1;
    c.inertia.inverse_mass[j] = c.asleep_inertia.inverse_mass[j];
    c.inertia.inverse_moment[j] = c.asleep_inertia.inverse_moment[j];
    c.still_for[j] = 0.0;
  }
}

bool wake_touched(StepContext& c) {
  bool woke = false;
  for (const ShapePair& p : c.pairs) {
    const BodyId a = c.shapes[p.first].body;
    const BodyId b = c.shapes[p.second].body;
    // The broadphase pairs a sleeping body only with an awake dynamic one.
    for (BodyId j : {a, b}) {
      if (asleep(c, j)) {
        wake_island(c, j);
        woke = true;
      }
    }
  }
  // Kinematic bodies are not dynamic, so the broadphase does not pair them with sleeping ones.
  for (BodyId k : c.kinematic) {
    if (!kinematic_moves(c, k)) continue;
    for (auto [i, last] = c.shapes.of_body(k); i < last; ++i) {
      const Aabb swept = c.world_start.bounds(i)
                             .united(c.end_bounds.bounds(i))
                             .fattened(c.settings.contact_margin);
      for (std::uint32_t s = 0; s < c.shapes.size(); ++s) {
        const BodyId j = c.shapes[s].body;
        if (asleep(c, j) && swept.overlaps(c.world_start.bounds(s))) {
          wake_island(c, j);
          woke = true;
        }
      }
    }
  }
  return woke;
}

void hold_sleeping(StepContext& c) {
  for (BodyId j : c.forces.bodies()) {
    if (!asleep(c, j)) continue;
    c.state.position[j] = c.start.position[j];
    c.state.angle[j] = c.start.angle[j];
    c.state.velocity[j] = Vec2::Zero();
    c.state.angular_velocity[j] = 0.0;
  }
}

void fall_asleep(StepContext& c, SleepScratch& scratch) {
  const Settings& s = c.settings;
  const std::vector<BodyId>& bodies = c.forces.bodies();
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const BodyId j = bodies[k];
    if (asleep(c, j)) continue;
    const bool still = c.forces.gravity_only(k) && c.state.velocity[j].norm() < s.sleep_speed &&
                       std::abs(c.state.angular_velocity[j]) < s.sleep_angular_speed;
    c.still_for[j] = still ? c.still_for[j] + c.h : 0.0;
  }
  // Islands: dynamic bodies joined by their contacts (static bodies join nothing).
  std::vector<BodyId>& parent = scratch.parent;
  parent.resize(c.dynamic.size());
  std::iota(parent.begin(), parent.end(), BodyId{0});
  for (const Contact& contact : c.contacts) {
    if (!c.dynamic[contact.body_a] || !c.dynamic[contact.body_b]) continue;
    parent[root_of(parent, contact.body_a)] = root_of(parent, contact.body_b);
  }
  // An island is still for as long as its least still body; kept at its root.
  std::vector<double>& island_still = scratch.least_still;
  island_still.assign(parent.size(), s.time_to_sleep);
  for (BodyId j : bodies) {
    if (!asleep(c, j)) {
      double& least = island_still[root_of(parent, j)];
      least = std::min(least, c.still_for[j]);
    }
  }
  for (BodyId j : bodies) {
    if (asleep(c, j)) continue;
    const BodyId root = root_of(parent, j);
    if (island_still[root] < s.time_to_sleep) continue;
    c.sleep_island[j] = root;
    c.asleep_inertia.inverse_mass[j] = c.inertia.inverse_mass[j];
    c.asleep_inertia.inverse_moment[j] = c.inertia.inverse_moment[j];
    c.inertia.inverse_mass[j] = 0.0;
    c.inertia.inverse_moment[j] = 0.0;
    c.dynamic[j] = 0;
    c.state.velocity[j] = Vec2::Zero();
    c.state.angular_velocity[j] = 0.0;
  }
}

}  // namespace gp
