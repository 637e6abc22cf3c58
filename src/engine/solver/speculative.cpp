#include "engine/solver/speculative.hpp"

#include "engine/geometry/transform.hpp"
#include "engine/solver/position_passes.hpp"
#include "engine/solver/velocity_passes.hpp"

namespace gp {

namespace {

// Where a body ends once this stage has moved it by h × each velocity change it makes: at its
// place at the start plus h × its end velocity, plus what its place lags behind h × its velocity
// now [m, rad]. A body falling freely lags by −a h²/2, the bend of its parabola; one held by
// resting contacts, whose impulses moved it by half of h × Δv, by about nothing.
struct Lag {
  Vec2 linear;
  double angular;
};

Lag lag_of(const MotionState& start, const MotionState& s, BodyId b, double h) {
  // The angular lag is a fraction of a radian; an angle that wrapped over the step is 2π off.
  return {s.position[b] - start.position[b] - h * s.velocity[b],
          within_half_turn(s.angle[b] - start.angle[b] - h * s.angular_velocity[b])};
}

// The targets of the speculative points whose gaps are within twice their bodies' lag: the
// normal velocity that closes the gap by the end of the step, the lag counted. Aimed at the gap
// alone (gap / h), a body falling onto the floor stops a h²/2 short of it, and a pile's body that
// far above the floor stays there step after step, moving at the speed that would close the gap
// (1.36 mm and 0.082 m/s at 60 Hz). A wider gap is still aimed at alone: a fast body then stops a
// lag short and lands at the next step, slowly, where landing at once would leave it approaching
// fast, which the resting contact stops by overlapping half of h × its speed.
void close_within_lag(ContactSet& speculative, const MotionState& start, const MotionState& s,
                      double h, const Settings& settings) {
  const double touching = touching_gap(settings, h);
  for (const Contact& c : speculative) {
    const Lag a = lag_of(start, s, c.body_a, h);
    const Lag b = lag_of(start, s, c.body_b, h);
    for (ContactPointState& p : speculative.points(c)) {
      const double lag = (a.linear - b.linear).dot(c.normal) + a.angular * p.normal_arm_a -
                         b.angular * p.normal_arm_b;  // m, along the normal
      if (lag > 0.0 && -p.depth <= 2.0 * lag) {
        p.target_normal_velocity = closing_target(p.depth - lag, h, touching);
      }
    }
  }
}

}  // namespace

void solve_speculative(StepContext& ctx, std::span<const std::uint32_t> stored_at,
                       SpeculativeScratch& scratch) {
  ContactSet& resting = ctx.contacts;
  ContactSet& speculative = ctx.speculative_contacts;
  const BodyInertia& inertia = ctx.inertia;
  const Settings& settings = ctx.settings;
  const double h = ctx.h;
  MotionState& s = ctx.state;
  // An impact's impulse fades as it spreads through a heap: the resting contacts up to this many
  // contacts away from it are solved with it, the rest of the heap holds still for it.
  constexpr int kReach = 2;
  scratch.reached.assign(s.position.size(), 0);
  scratch.included.assign(resting.size(), 0);
  scratch.nearby.clear();
  for (const Contact& c : speculative) {
    scratch.reached[c.body_a] = inertia.inverse_mass[c.body_a] > 0.0;
    scratch.reached[c.body_b] = inertia.inverse_mass[c.body_b] > 0.0;
  }
  for (int level = 0; level < kReach; ++level) {
    scratch.newly.clear();
    for (std::uint32_t k = 0; k < resting.size(); ++k) {
      const std::uint32_t i = stored_at.empty() ? k : stored_at[k];
      const Contact& c = resting[i];
      if (scratch.included[i] || !(scratch.reached[c.body_a] || scratch.reached[c.body_b]))
        continue;
      scratch.included[i] = 1;
      scratch.nearby.push_back(i);
      for (BodyId b : {c.body_a, c.body_b}) {
        if (inertia.inverse_mass[b] > 0.0) scratch.newly.push_back(b);
      }
    }
    for (BodyId b : scratch.newly) scratch.reached[b] = 1;
  }
  // The lags are read before the stage moves anything.
  prepare_contacts(speculative, ctx.shapes, inertia, ctx.start, h, settings);
  close_within_lag(speculative, ctx.start, s, h, settings);
  // What the resting impulses add from here on moves the bodies by h × Δv: take back h × their
  // impulses so far, and give h × their final impulses at the end.
  for (const std::uint32_t i : scratch.nearby)
    move_by_contact_impulse(resting, resting[i], inertia, -h, s);
  for (int pass = 0; pass < settings.velocity_iterations; ++pass) {
    for (const std::uint32_t i : scratch.nearby)
      solve_contact_once(resting, resting[i], inertia, s);
    for (const Contact& c : speculative) solve_contact_once(speculative, c, inertia, s);
  }
  apply_restitution(speculative, inertia, s);
  for (const std::uint32_t i : scratch.nearby)
    move_by_contact_impulse(resting, resting[i], inertia, h, s);
  move_by_contact_impulses(speculative, inertia, h, s);
}

}  // namespace gp
