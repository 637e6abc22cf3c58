#include "engine/solver/speculative.hpp"

#include "engine/solver/position_passes.hpp"
#include "engine/solver/velocity_passes.hpp"

namespace gp {

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
  // What the resting impulses add from here on moves the bodies by h × Δv: take back h × their
  // impulses so far, and give h × their final impulses at the end.
  for (const std::uint32_t i : scratch.nearby)
    move_by_contact_impulse(resting, resting[i], inertia, -h, s);
  prepare_contacts(speculative, ctx.shapes, inertia, ctx.start, h, settings);
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
