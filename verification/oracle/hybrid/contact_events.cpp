#include "verification/oracle/hybrid/contact_events.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "gamephysics/models/dd/kinetic_energy.hpp"
#include "verification/oracle/contact/contact_modes.hpp"
#include "verification/oracle/contact/impacts.hpp"
#include "verification/oracle/contact/projection.hpp"
#include "verification/oracle/geometry/contact_geometry.hpp"
#include "verification/oracle/model/applied_forces.hpp"

namespace gp::oracle {

using verification::message_number;
using verification::OracleDomainError;
using verification::OracleEvent;

namespace {

// The share of the kinetic energy an impact may gain by round-off of its impulses.
constexpr double kEnergyRoundOff = 1e-10;

// J: DD:kEnergy summed over the bodies that move under forces (the others' velocities are fixed).
double kinetic_energy(const World& world, std::span<const Vec2> velocity,
                      std::span<const double> angular_velocity) {
  double e = 0.0;
  for (std::size_t b = 0; b < world.bodies.size(); ++b) {
    const RigidBody& body = world.bodies[b];
    if (body.type != BodyType::Dynamic) continue;
    e += dd::kinetic_energy(body.mass, velocity[b], body.moment, angular_velocity[b]);
  }
  return e;
}

}  // namespace

ContactEvents::ContactEvents(HybridSystem& system, EventWatch& watch,
                             const verification::OracleOptions& options)
    : system_(system), watch_(watch), options_(options) {}

std::string ContactEvents::describe(std::size_t a, std::size_t b) const {
  const World& w = system_.world();
  return "bodies '" + w.bodies[a].name + "' and '" + w.bodies[b].name + "'";
}

void ContactEvents::detect(std::size_t p, std::span<const Motion> motions,
                           std::vector<ActiveContact>& contacts) const {
  const World& w = system_.world();
  const HullPair& pair = watch_.pairs()[p];
  const ContactGeometry g =
      contact_geometry(w.bodies[pair.body_a].hulls[pair.hull_a], pose_of(motions[pair.body_a]),
                       w.bodies[pair.body_b].hulls[pair.hull_b], pose_of(motions[pair.body_b]),
                       options_.contact_tolerance);
  for (const ContactPoint& point : g.points) {
    if (point.separation > options_.contact_tolerance) continue;
    const ActiveContact c = make_active_contact(w, pair, p, point.feature);
    const bool known = std::any_of(contacts.begin(), contacts.end(),
                                   [&](const ActiveContact& o) { return same_contact(o, c); });
    if (!known) contacts.push_back(c);
  }
}

void ContactEvents::start(double t, double* y, std::vector<OracleEvent>& impacts) {
  std::vector<Motion> motions(system_.states().body_count());
  system_.states().motions_at(t, y, motions);
  require_apart(t, y);
  std::vector<ActiveContact> candidates;
  for (std::size_t p = 0; p < watch_.pairs().size(); ++p) {
    if (watch_.distance(p, motions) <= options_.contact_tolerance) detect(p, motions, candidates);
  }
  settle(t, motions, std::move(candidates), y, impacts);
}

void ContactEvents::handle(double t, double* y, std::span<const int> crossed,
                           std::vector<OracleEvent>& impacts) {
  std::vector<Motion> motions(system_.states().body_count());
  system_.states().motions_at(t, y, motions);
  const std::vector<ActiveContact>& before = system_.contacts();
  // Where the root finder stopped, the solution is interpolated between two projected steps:
  // back onto the constraints first, so that their drift is not taken for separation or slip.
  project_onto_contacts(system_.world(), before, motions);
  std::vector<bool> dropped(before.size(), false);
  std::vector<ActiveContact> candidates = before;
  std::vector<std::size_t> redetect;
  for (std::size_t r = 0; r < crossed.size(); ++r) {
    if (crossed[r] == 0) continue;
    const Root& root = watch_.root(r);
    switch (root.kind) {
      case RootKind::Approach:
        redetect.push_back(root.index);
        break;
      case RootKind::LiftOff:
        dropped[root.index] = true;
        break;
      case RootKind::StickLimit:
        // The friction reached +μ f_n (side 0) or −μ f_n: the contact slips against it.
        candidates[root.index].mode = ContactMode::Sliding;
        candidates[root.index].slip_sign = root.detail == 0 ? -1 : 1;
        break;
      case RootKind::SlipStop:
        candidates[root.index].mode = ContactMode::Sticking;
        candidates[root.index].slip_sign = 0;
        break;
      case RootKind::OffEdge:
      case RootKind::OffCorner:
      case RootKind::Landing:
        redetect.push_back(before[root.index].pair);
        break;
    }
  }
  std::vector<ActiveContact> kept;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const bool redone =
        std::find(redetect.begin(), redetect.end(), candidates[i].pair) != redetect.end();
    if (!dropped[i] && !redone) kept.push_back(candidates[i]);
  }
  for (std::size_t p : redetect) detect(p, motions, kept);
  // Pairs touching within the tolerance join too, though their own roots have not fired yet:
  // impacts a hair apart in time (a row of discs landing on another) are one simultaneous impact,
  // not a rapid sequence of single ones.
  std::vector<bool> in_contact(watch_.pairs().size(), false);
  for (const ActiveContact& c : kept) in_contact[c.pair] = true;
  for (std::size_t p = 0; p < watch_.pairs().size(); ++p) {
    if (!in_contact[p] && watch_.distance(p, motions) <= options_.contact_tolerance) {
      detect(p, motions, kept);
    }
  }
  // A contact whose lift-off fired stays dropped though it still touches: its force is past
  // −floor, below what the mode LCP tells from zero, and kept it would be armed with a lift-off
  // root already negative that never changes sign again, and pull.
  std::erase_if(kept, [&](const ActiveContact& c) {
    for (std::size_t i = 0; i < before.size(); ++i) {
      if (dropped[i] && same_contact(before[i], c)) return true;
    }
    return false;
  });
  settle(t, motions, std::move(kept), y, impacts);
}

void ContactEvents::settle(double t, std::vector<Motion>& motions,
                           std::vector<ActiveContact> candidates, double* y,
                           std::vector<OracleEvent>& impacts) {
  const World& w = system_.world();
  // Every touching pair starts exactly touching, those about to part too: one left a round-off
  // inside the other would sit on its approach root and be found touching again at once.
  project_positions(w, candidates, motions);
  std::vector<ContactKinematics> k = kinematics_of(candidates, motions);
  const bool approaching = std::any_of(k.begin(), k.end(), [&](const ContactKinematics& ki) {
    return ki.gap_rate < -options_.speed_tolerance;
  });
  if (approaching) {
    std::vector<Vec2> velocity;
    std::vector<double> angular_velocity;
    for (const Motion& m : motions) {
      velocity.push_back(m.velocity);
      angular_velocity.push_back(m.angular_velocity);
    }
    const double before = kinetic_energy(w, velocity, angular_velocity);
    std::vector<Impulse> p;
    try {
      p = resolve_impacts(w, candidates, k, options_.rest_speed, velocity, angular_velocity);
    } catch (const std::runtime_error& e) {
      throw OracleDomainError(
          std::string("the impact has no solution Lemke's method reaches: ") + e.what(), t);
    }
    const double after = kinetic_energy(w, velocity, angular_velocity);
    // A kinematic body is an unbounded source of energy (a paddle bats a ball): no check there.
    const bool closed = std::none_of(candidates.begin(), candidates.end(), [&](const auto& c) {
      return w.bodies[c.first].type == BodyType::Kinematic ||
             w.bodies[c.second].type == BodyType::Kinematic;
    });
    if (closed && after > before * (1.0 + kEnergyRoundOff)) {
      throw OracleDomainError("an impact gains energy (" + message_number(before) + " J to " +
                                  message_number(after) +
                                  " J): Newton's law of restitution with friction can, and then "
                                  "is no model of it",
                              t);
    }
    for (std::size_t b = 0; b < motions.size(); ++b) {
      motions[b].velocity = velocity[b];
      motions[b].angular_velocity = angular_velocity[b];
    }
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      if (p[i].normal <= 0.0) continue;
      // Reported as the pair's bodies A and B, with the normal from B towards A.
      const HullPair& pair = watch_.pairs()[candidates[i].pair];
      const double sign = candidates[i].first == pair.body_a ? 1.0 : -1.0;
      // + 0 turns a −0 component into 0 for the impact log.
      const Vec2 normal = sign * k[i].normal + Vec2::Zero();
      impacts.push_back({t, pair.body_a, pair.body_b, normal, k[i].point, p[i].normal});
    }
    k = kinematics_of(candidates, motions);
  }
  std::vector<ActiveContact> touching;
  std::vector<ContactKinematics> touching_k;
  // After an impact, a contact leaving slower than the rest speed stays (its speed is put to
  // zero by the projection): a disc dropped into a wedge would otherwise bounce between the two
  // sides in an endless sequence of ever slower impacts, as an inelastic ball does on the ground.
  const double leaving = approaching ? options_.rest_speed : options_.speed_tolerance;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (k[i].gap_rate > leaving) continue;
    touching.push_back(candidates[i]);
    touching_k.push_back(k[i]);
  }
  std::vector<Vec2> linear(motions.size(), Vec2::Zero());
  std::vector<double> angular(motions.size(), 0.0);
  applied_accelerations(w, motions, linear, angular);
  if (!choose_contact_modes(w, touching, touching_k, linear, angular, options_.speed_tolerance)) {
    throw OracleDomainError(
        "the contact forces have no solution (a frictional paradox of Painlevé's kind)", t);
  }
  largest_drift_ = std::max(largest_drift_, project_onto_contacts(w, touching, motions));
  std::vector<bool> held(watch_.pairs().size(), false);
  for (const ActiveContact& c : touching) held[c.pair] = true;
  const std::array<const std::vector<ActiveContact>*, 2> groups = {&candidates,
                                                                   &system_.contacts()};
  for (const std::vector<ActiveContact>* group : groups) {
    const std::vector<ContactKinematics> parting = kinematics_of(*group, motions);
    for (std::size_t i = 0; i < group->size(); ++i) {
      const std::size_t p = (*group)[i].pair;
      if (!held[p] && parting[i].gap_rate <= options_.rest_speed) watch_.release(p);
    }
  }
  system_.set_contacts(std::move(touching));
  system_.states().values_of(motions, y);
}

void ContactEvents::note_drift(double t, const double* y) {
  std::vector<Motion> motions(system_.states().body_count());
  system_.states().motions_at(t, y, motions);
  for (const ContactKinematics& k : kinematics_of(system_.contacts(), motions)) {
    largest_drift_ = std::max(largest_drift_, std::abs(k.gap));
  }
}

void ContactEvents::require_pushing(const Snapshot& snapshot) const {
  // Twice the floor: the root finder stops just past −floor, and a projection moves f_n by
  // round-off.
  const double least = -2.0 * watch_.force_floor();
  for (std::size_t i = 0; i < snapshot.forces.size(); ++i) {
    if (!snapshot.forces[i].unique || snapshot.forces[i].normal >= least) continue;
    const ActiveContact& c = system_.contacts()[i];
    throw OracleDomainError(describe(c.first, c.second) + " pull each other with " +
                                message_number(snapshot.forces[i].normal) +
                                " N at an active contact: a lift-off the oracle missed",
                            snapshot.time);
  }
}

void ContactEvents::require_apart(double t, const double* y) const {
  std::vector<Motion> motions(system_.states().body_count());
  system_.states().motions_at(t, y, motions);
  std::vector<bool> in_contact(watch_.pairs().size(), false);
  for (const ActiveContact& c : system_.contacts()) in_contact[c.pair] = true;
  for (std::size_t p = 0; p < watch_.pairs().size(); ++p) {
    if (in_contact[p]) continue;
    const double d = watch_.distance(p, motions);
    if (d < -options_.contact_tolerance) {
      const HullPair& pair = watch_.pairs()[p];
      throw OracleDomainError(describe(pair.body_a, pair.body_b) + " overlap by " +
                                  message_number(-d) +
                                  " m: the oracle needs them apart (or an impact it could "
                                  "not locate: a grazing contact)",
                              t);
    }
  }
}

}  // namespace gp::oracle
