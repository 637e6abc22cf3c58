// Conservation over long runs: linear and angular momentum and energy of the two-body orbit
// under pairwise gravitation, and the energy of elastic discs bouncing in a closed box.
#include <cmath>

#include "engine/scene/run.hpp"
#include "engine/scene/scene_space.hpp"
#include "verification/quantities/mechanical_quantities.hpp"
#include "verification/suite/scene_builders.hpp"
#include "verification/suite/suite.hpp"

namespace gp::verification {

namespace {

struct Drift {
  double momentum = 0.0;          ///< largest |p − p₀| / Σ m|v₀|
  double angular_momentum = 0.0;  ///< largest |L − L₀| / |L₀|
  double energy = 0.0;            ///< largest |E − E₀| / |E₀|
  double energy_gain = 0.0;       ///< largest (E − E₀) / |E₀|, ≤ 0 when energy never grows
};

Drift drift_over(const Scene& scene, long steps) {
  const auto space = build_space(scene);
  const Invariants start = invariants(*space);
  double momentum_scale = 0.0;  // Σ m|v|: the size of the terms whose sum is conserved
  for (BodyId id = 0; id < space->body_count(); ++id) {
    if (space->type(id) == BodyType::Dynamic) {
      momentum_scale += space->mass(id) * space->state(id).velocity.norm();
    }
  }
  Drift d;
  for (long k = 0; k < steps; ++k) {
    space->step(scene.dt);
    const Invariants now = invariants(*space);
    d.momentum = std::max(d.momentum, (now.momentum - start.momentum).norm() / momentum_scale);
    d.angular_momentum =
        std::max(d.angular_momentum, std::abs(now.angular_momentum - start.angular_momentum) /
                                         std::abs(start.angular_momentum));
    d.energy =
        std::max(d.energy, std::abs(now.energy() - start.energy()) / std::abs(start.energy()));
    d.energy_gain =
        std::max(d.energy_gain, (now.energy() - start.energy()) / std::abs(start.energy()));
  }
  return d;
}

// 16 elastic, frictionless discs in a closed 20 m square, no gravity, with impacts slower than
// `restitution_threshold` [m/s] made inelastic.
Scene elastic_box(double restitution_threshold) {
  Scene s = make_scene(Vec2::Zero(), 1.0 / 60, 0.0);
  s.settings.restitution_threshold = restitution_threshold;
  s.bodies.push_back(wall("bottom", {-10, -10}, {10, -10}, 1.0));
  s.bodies.push_back(wall("top", {-10, 10}, {10, 10}, 1.0));
  s.bodies.push_back(wall("left", {-10, -10}, {-10, 10}, 1.0));
  s.bodies.push_back(wall("right", {10, -10}, {10, 10}, 1.0));
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      s.bodies.push_back(disc(std::string("d") + std::to_string(4 * i + j),
                              {-6.0 + 4.0 * i, -6.0 + 4.0 * j},
                              {std::sin(1.0 + 3.0 * i + j), std::cos(2.0 * i - j)}, 0.5, 1.0));
    }
  }
  return s;
}

}  // namespace

std::vector<Check> conservation_checks(const std::vector<NamedScene>& scenes,
                                       const SuiteOptions& o) {
  CheckList list("conservation over long runs");
  const long steps = o.quick ? 1000 : 100000;
  const std::string n = std::to_string(steps) + " steps";
  for (const auto& [name, scene] : scenes) {
    if (!scene.settings.G) continue;
    if (o.progress) *o.progress << "  conservation: " << name << ", " << n << "\n";
    const Drift d = drift_over(scene, steps);
    list.within(name + ", velocity_verlet, " + n, "TM:NewtonThirdLawMot TM:UniversalGravLaw",
                "linear momentum drift " + figure(d.momentum) + " (relative to Σ m|v|)",
                "≤ 1e-13 relative: equal and opposite forces", {{d.momentum, 1e-13}});
    list.within(name + ", velocity_verlet, " + n, "IM:transMot GD:accelGravity",
                "angular momentum drift " + figure(d.angular_momentum) + " (relative)",
                "≤ 3e-13 relative: central forces, symmetric integrator",
                {{d.angular_momentum, 3e-13}});
    list.within(name + ", velocity_verlet, " + n, "DD:kEnergy IM:transMot",
                "energy drift " + figure(d.energy) + " (relative)",
                "≤ 2e-11 relative and bounded: symplectic integrator", {{d.energy, 2e-11}});
  }
  if (o.progress) *o.progress << "  conservation: elastic discs in a box, " << n << "\n";
  // Without the restitution threshold every impact is elastic (IM:col2D with C_R = 1), so the
  // energy is conserved to rounding.
  const Drift elastic = drift_over(elastic_box(0.0), steps);
  list.within("16 elastic discs in a closed box, C_R = 1, μ = 0, restitution threshold 0, " + n,
              "IM:col2D GD:impulse DD:kEnergy",
              "energy drift " + figure(elastic.energy) + " (relative)",
              "≤ 1e-13 relative: every impact conserves energy", {{elastic.energy, 1e-13}});
  // With the default threshold (0.05 m/s) impacts slower than it are inelastic on purpose (they
  // end Zeno sequences of bounces): energy is lost, never gained.
  const Drift box = drift_over(elastic_box(Settings{}.restitution_threshold), steps);
  list.within("the same, default restitution threshold 0.05 m/s, " + n,
              "IM:col2D GD:impulse DD:kEnergy",
              "energy lost " + figure(box.energy) + ", largest gain " + figure(box.energy_gain) +
                  " (relative)",
              "loses ≤ 0.1 (slow impacts are inelastic by design), gains ≤ 1e-14 (rounding)",
              {{box.energy, 0.1}, {box.energy_gain, 1e-14}});
  return list.rows();
}

}  // namespace gp::verification
