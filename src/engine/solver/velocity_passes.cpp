#include "engine/solver/velocity_passes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "engine/geometry/transform.hpp"
#include "engine/solver/direction_pair.hpp"
#include "engine/solver/single_point_lanes.hpp"
#include "engine/solver/two_point_lanes.hpp"
#include "gamephysics/models/dd/angular_displacement.hpp"
#include "gamephysics/models/dd/impulse.hpp"
#include "gamephysics/models/dd/torque.hpp"
#include "gamephysics/models/gd/collision_impulse.hpp"
#include "gamephysics/models/im/collision_response.hpp"
#include "gamephysics/models/tm/newton_third_law.hpp"

namespace gp {

namespace {

// Effective masses of the two bodies at a point along the normal and the tangent [kg], in lanes
// 0 and 1: GD:impulse with C_R = 0 gives, for a unit closing speed, exactly the impulse per unit
// change of speed. Both directions at once: a division costs as much as the rest of the formula.
DoublePair effective_masses(const BodyInertia& m, const Contact& c, const Vec2& arm_a,
                            const Vec2& arm_b, const Vec2& tangent) {
  const Vec2Pair directions{{c.normal.x(), tangent.x()}, {c.normal.y(), tangent.y()}};
  return gd::collision_impulse<DoublePair, double, Vec2Pair, Vec2Pair, double, double, Vec2>(
      0.0, -directions, directions, m.inverse_mass[c.body_a], m.inverse_mass[c.body_b],
      m.inverse_moment[c.body_a], m.inverse_moment[c.body_b], arm_a, arm_b);
}

// The velocities and inverse inertias of a contact's two bodies, copied out of the state arrays
// while its points are solved: the inner loop then reads two cache lines rather than eight
// arrays.
struct PairMotion {
  Vec2 velocity_a, velocity_b;
  double angular_velocity_a, angular_velocity_b;
  double inverse_mass_a, inverse_mass_b, inverse_moment_a, inverse_moment_b;

  PairMotion(const Contact& c, const BodyInertia& m, const MotionState& s)
      : velocity_a(s.velocity[c.body_a]),
        velocity_b(s.velocity[c.body_b]),
        angular_velocity_a(s.angular_velocity[c.body_a]),
        angular_velocity_b(s.angular_velocity[c.body_b]),
        inverse_mass_a(m.inverse_mass[c.body_a]),
        inverse_mass_b(m.inverse_mass[c.body_b]),
        inverse_moment_a(m.inverse_moment[c.body_a]),
        inverse_moment_b(m.inverse_moment[c.body_b]) {}

  // Only movable bodies are written: a static or kinematic body may be in contacts solved on
  // other threads at the same time, and its motion does not change. Inverse masses and moments
  // are at least 0, so their sum, both at hand, tells a movable body in one comparison (movable()
  // takes two, each with its own test for NaN: 0.9% of rain1000's instructions).
  void store(const Contact& c, MotionState& s) const {
    if (inverse_mass_a + inverse_moment_a > 0.0) {
      s.velocity[c.body_a] = velocity_a;
      s.angular_velocity[c.body_a] = angular_velocity_a;
    }
    if (inverse_mass_b + inverse_moment_b > 0.0) {
      s.velocity[c.body_b] = velocity_b;
      s.angular_velocity[c.body_b] = angular_velocity_b;
    }
  }

  double velocity_along(const Vec2& d, double arm_a, double arm_b) const {
    return gp::velocity_along(velocity_a - velocity_b, angular_velocity_a, angular_velocity_b, d,
                              arm_a, arm_b);
  }
  double normal_velocity(const Contact& c, const ContactPointState& p) const {
    return velocity_along(c.normal, p.normal_arm_a, p.normal_arm_b);
  }
  double tangent_velocity(const Vec2& tangent, const ContactPointState& p) const {
    return velocity_along(tangent, p.tangent_arm_a, p.tangent_arm_b);
  }

  /// Applies the impulse j d [N·s] to A at a point whose arms crossed with d are `arm_a` and
  /// `arm_b` [m], and the reaction to B (DD:impulseV, DD:torque, TM:NewtonThirdLawMot).
  void push_along(const Vec2& d, double arm_a, double arm_b, double j) {
    const Vec2 impulse = j * d;
    velocity_a += dd::velocity_change_from_impulse(impulse, inverse_mass_a);
    angular_velocity_a += j * arm_a * inverse_moment_a;
    velocity_b += dd::velocity_change_from_impulse(tm::reaction_force(impulse), inverse_mass_b);
    angular_velocity_b -= j * arm_b * inverse_moment_b;
  }
  void push_normal(const Contact& c, const ContactPointState& p, double j) {
    push_along(c.normal, p.normal_arm_a, p.normal_arm_b, j);
  }
  void push_tangent(const Vec2& tangent, const ContactPointState& p, double j) {
    push_along(tangent, p.tangent_arm_a, p.tangent_arm_b, j);
  }
};

}  // namespace

double normal_coupling(const Contact& ci, const ContactPointState& pi, const Contact& cj,
                       const ContactPointState& pj, const BodyInertia& m) {
  const double directions = ci.normal.dot(cj.normal);
  const auto shared = [&](BodyId bi, double arm_i, BodyId bj, double arm_j) {
    return bi == bj
               ? body_coupling(m.inverse_mass[bi], m.inverse_moment[bi], directions, arm_i, arm_j)
               : 0.0;
  };
  return shared(ci.body_a, pi.normal_arm_a, cj.body_a, pj.normal_arm_a) -
         shared(ci.body_a, pi.normal_arm_a, cj.body_b, pj.normal_arm_b) -
         shared(ci.body_b, pi.normal_arm_b, cj.body_a, pj.normal_arm_a) +
         shared(ci.body_b, pi.normal_arm_b, cj.body_b, pj.normal_arm_b);
}

void apply_contact_impulse(const Contact& c, const ContactPointState& p, double normal,
                           double tangent, const BodyInertia& inertia, MotionState& s) {
  PairMotion m(c, inertia, s);
  m.push_normal(c, p, normal);
  m.push_tangent(contact_tangent(c.normal), p, tangent);
  m.store(c, s);
}

namespace {

// Both normal constraints of an edge-to-edge contact at once, as a 2 × 2 linear complementarity
// problem solved by enumerating its four cases (Box2D's block solver): solving the two points one
// after the other leaves a residual that turns a tall stack. Returns false, leaving the points to
// the one-by-one solver, when the two points are nearly redundant (ill-conditioned matrix).
bool solve_pair(const Contact& c, const NormalBlock& k, ContactPointState& p, ContactPointState& q,
                PairMotion& m) {
  if (!k.solvable()) return false;
  const Vec2 old{p.normal_impulse, q.normal_impulse};
  // Velocities the constraints must reach, less what the impulses already applied give.
  const Vec2 b{
      m.normal_velocity(c, p) - p.target_normal_velocity - (k.k11 * old.x() + k.k12 * old.y()),
      m.normal_velocity(c, q) - q.target_normal_velocity - (k.k12 * old.x() + k.k22 * old.y())};
  Vec2 x;
  if (x = Vec2{-(k.inverse11 * b.x() + k.inverse12 * b.y()),
               -(k.inverse12 * b.x() + k.inverse22 * b.y())};
      x.x() >= 0.0 && x.y() >= 0.0) {
  } else if (x = Vec2{-b.x() * p.normal_mass, 0.0}; x.x() >= 0.0 && k.k12 * x.x() + b.y() >= 0.0) {
  } else if (x = Vec2{0.0, -b.y() * q.normal_mass}; x.y() >= 0.0 && k.k12 * x.y() + b.x() >= 0.0) {
  } else if (x = Vec2::Zero(); b.x() >= 0.0 && b.y() >= 0.0) {
  } else {
    return false;
  }
  m.push_normal(c, p, x.x() - old.x());
  m.push_normal(c, q, x.y() - old.y());
  p.normal_impulse = x.x();
  q.normal_impulse = x.y();
  return true;
}

// Whether a pass over `c` would change nothing: no point pushes or rubs yet, and none would
// have to, because each already separates at least as fast as its target asks (a speculative
// point whose gap the step does not close). Friction cannot act without a normal impulse.
template <std::size_t N>
bool idle(const Contact& c, std::span<ContactPointState, N> points, const PairMotion& m) {
  for (const ContactPointState& p : points) {
    if (p.normal_impulse != 0.0 || p.tangent_impulse != 0.0 ||
        m.normal_velocity(c, p) < p.target_normal_velocity) {
      return false;
    }
  }
  return true;
}

// One pass of sequential impulses over the N points of `c`: friction, then the normal
// constraints. Returns the largest change of an accumulated impulse in the pass [N·s]. N is a
// template parameter so that the loops over the points unroll: a pass's cost per contact is mostly
// such bookkeeping.
template <std::size_t N>
double solve_contact(const ContactSet& contacts, const Contact& c,
                     std::span<ContactPointState, N> points, PairMotion& m) {
  if (idle(c, points, m)) return 0.0;
  double largest_change = 0.0;
  if (c.friction > 0.0) {
    // Friction first, so the normal constraints, solved last, are the ones met exactly.
    const Vec2 tangent = contact_tangent(c.normal);
    for (ContactPointState& p : points) {
      const double limit = c.friction * p.normal_impulse;
      const double change = -p.tangent_mass * m.tangent_velocity(tangent, p);
      const double total = std::clamp(p.tangent_impulse + change, -limit, limit);
      largest_change = std::max(largest_change, std::abs(total - p.tangent_impulse));
      m.push_tangent(tangent, p, total - p.tangent_impulse);
      p.tangent_impulse = total;
    }
  }
  if constexpr (N == 2) {
    const Vec2 old{points[0].normal_impulse, points[1].normal_impulse};
    if (solve_pair(c, contacts.block(c), points[0], points[1], m)) {
      return std::max({largest_change, std::abs(points[0].normal_impulse - old.x()),
                       std::abs(points[1].normal_impulse - old.y())});
    }
  }
  for (ContactPointState& p : points) {
    const double change = p.normal_mass * (p.target_normal_velocity - m.normal_velocity(c, p));
    const double total = std::max(p.normal_impulse + change, 0.0);
    largest_change = std::max(largest_change, std::abs(total - p.normal_impulse));
    m.push_normal(c, p, total - p.normal_impulse);
    p.normal_impulse = total;
  }
  return largest_change;
}

}  // namespace

double apply_collision_response(const Contact& c, const ContactPointState& p, double restitution,
                                const BodyInertia& inertia, MotionState& s) {
  const im::CollidingBody body_a{inertia.inverse_mass[c.body_a], inertia.inverse_moment[c.body_a],
                                 s.velocity[c.body_a], s.angular_velocity[c.body_a], arm_a(c, p)};
  const im::CollidingBody body_b{inertia.inverse_mass[c.body_b], inertia.inverse_moment[c.body_b],
                                 s.velocity[c.body_b], s.angular_velocity[c.body_b], arm_b(c, p)};
  const auto r = im::collision_response(body_a, body_b, c.normal, restitution);
  s.velocity[c.body_a] = r.velocity_a;
  s.angular_velocity[c.body_a] = r.angular_velocity_a;
  s.velocity[c.body_b] = r.velocity_b;
  s.angular_velocity[c.body_b] = r.angular_velocity_b;
  return r.impulse;
}

double contact_restitution(const BodyShapes& shapes, const Contact& c) {
  return std::max(shapes[c.shape_a].restitution, shapes[c.shape_b].restitution);
}

bool propagate_impacts(const ContactSet& contacts, const BodyShapes& shapes,
                       const BodyInertia& inertia, const Settings& settings, MotionState& s) {
  bool any = false;
  int passes = settings.velocity_iterations;
  for (bool struck = true; struck && passes-- > 0;) {
    struck = false;
    for (const Contact& c : contacts) {
      const double restitution = contact_restitution(shapes, c);
      if (restitution == 0.0) continue;
      for (const ContactPointState& p : contacts.points(c)) {
        if (p.depth <= -settings.linear_slop) continue;
        if (contact_normal_velocity(s, c, p) >= -settings.restitution_threshold) continue;
        apply_collision_response(c, p, restitution, inertia, s);
        struck = any = true;
      }
    }
  }
  return any;
}

namespace {

// The diagonal and the coupling of `k`, a two-point contact's block, into where the contact set
// keeps it: a block made apart and copied in is read back with wide loads that stall on the
// narrow stores that made it.
void fill_block_entries(const BodyInertia& inertia, const Contact& c, const ContactPointState& p,
                        const ContactPointState& q, NormalBlock& k) {
  const DoublePair diagonal = 1.0 / DoublePair{p.normal_mass, q.normal_mass};
  k.k11 = diagonal[0];
  k.k22 = diagonal[1];
  k.k12 = normal_coupling(c, p, c, q, inertia);
}

// The inverse of `k` from its entries, or all 0 where it is not solvable.
void invert_block(NormalBlock& k) {
  const double determinant = k.k11 * k.k22 - k.k12 * k.k12;
  // Box2D's bound on K's condition number, past which the block solve amplifies round-off.
  if (k.k11 * k.k11 < 1000.0 * determinant) {
    const DoublePair first_row = DoublePair{k.k22, -k.k12} / determinant;
    k.inverse11 = first_row[0];
    k.inverse12 = first_row[1];
    k.inverse22 = k.k11 / determinant;
  } else {
    k.inverse11 = k.inverse12 = k.inverse22 = 0.0;
  }
}

}  // namespace

namespace {

// A contact's points: their effective masses, targets and bounces. Returns the deepest point's
// overlap [m].
double prepare_points(ContactSet& contacts, std::uint32_t i, const ContactPreparation& in) {
  const BodyInertia& inertia = in.inertia;
  const Contact& c = contacts[i];
  const Vec2 tangent = contact_tangent(c.normal);
  const std::span<ContactPointState> points = contacts.points(c);
  double deepest = -std::numeric_limits<double>::infinity();
  for (ContactPointState& p : points) {
    deepest = std::max(deepest, static_cast<double>(p.depth));
    const Vec2 arm_a = gp::arm_a(c, p);
    const Vec2 arm_b = gp::arm_b(c, p);
    const DoublePair masses = effective_masses(inertia, c, arm_a, arm_b, tangent);
    p.normal_mass = masses[0];
    p.tangent_mass = masses[1];
    p.target_normal_velocity = closing_target(p.depth, in.h, touching_gap(in.settings, in.h));
  }
  // Without a shape that bounces, no point does, and its approach need not be measured.
  if (!contacts.keeps_bounce_velocities()) return deepest;
  const std::span<double> bounces = contacts.bounce_velocities(c);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double approach = contact_normal_velocity(in.before, c, points[k]);
    // A speculative point (still apart) bounces too if the solver ends up pushing on it:
    // apply_restitution acts only where the normal impulse is positive. The shapes' restitution
    // is looked up only then: a resting pile's points never approach that fast.
    bounces[k] = approach < -in.settings.restitution_threshold
                     ? contact_restitution(in.shapes, c) * approach
                     : 0.0;
  }
  return deepest;
}

// Each of `part`'s contacts prepared: its points, then the block of a two-point contact. Step by
// step over all of them, each step's divisions independent from contact to contact, so that the
// processor overlaps them rather than waiting on each contact's chain of three in turn. Returns
// the deepest point's overlap [m].
double prepare_part(ContactSet& contacts, std::span<const std::uint32_t> part,
                    const ContactPreparation& in) {
  double deepest = -std::numeric_limits<double>::infinity();
  for (const std::uint32_t i : part) deepest = std::max(deepest, prepare_points(contacts, i, in));
  for (const std::uint32_t i : part) {
    const Contact& c = contacts[i];
    if (c.count() == 2) {
      const std::span<const ContactPointState> points = contacts.points(c);
      fill_block_entries(in.inertia, c, points[0], points[1], contacts.block(c));
    }
  }
  for (const std::uint32_t i : part) {
    const Contact& c = contacts[i];
    if (c.count() == 2) invert_block(contacts.block(c));
  }
  return deepest;
}

void warm_start_contact(const ContactSet& contacts, std::uint32_t i, const BodyInertia& inertia,
                        MotionState& s) {
  const Contact& c = contacts[i];
  PairMotion m(c, inertia, s);
  for (const ContactPointState& p : contacts.points(c)) {
    m.push_normal(c, p, p.normal_impulse);
    m.push_tangent(contact_tangent(c.normal), p, p.tangent_impulse);
  }
  m.store(c, s);
}

}  // namespace

double touching_gap(const Settings& settings, double h) {
  return settings.velocity_tolerance * h;
}

void prepare_contacts(ContactSet& contacts, const BodyShapes& shapes, const BodyInertia& inertia,
                      const MotionState& before, double h, const Settings& settings) {
  const ContactPreparation in{shapes, inertia, before, h, settings};
  contacts.keep_bounce_velocities(shapes.any_bounce());
  for (std::uint32_t i = 0; i < contacts.size(); ++i) {
    prepare_part(contacts, std::span<const std::uint32_t>(&i, 1), in);
  }
}

void warm_start(const ContactSet& contacts, const BodyInertia& inertia, MotionState& s) {
  for (std::uint32_t i = 0; i < contacts.size(); ++i) warm_start_contact(contacts, i, inertia, s);
}

double prepare_and_warm_start(const ContactBatches& batches, ContactSet& contacts,
                              const ContactPreparation& preparation, MotionState& s) {
  contacts.keep_bounce_velocities(preparation.shapes.any_bounce());
  // A contact's preparation stands alone, and its chain of divisions (its effective masses, then
  // its block's inverse) is long: several contacts prepared at once overlap theirs. Their warm
  // starts follow, in their order.
  constexpr std::size_t kPreparedAtOnce = 16;
  return batches.run_in_stretches([&](std::span<const std::uint32_t> stretch) {
    double deepest = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < stretch.size(); k += kPreparedAtOnce) {
      const auto part = stretch.subspan(k, std::min(kPreparedAtOnce, stretch.size() - k));
      deepest = std::max(deepest, prepare_part(contacts, part, preparation));
      for (const std::uint32_t i : part) warm_start_contact(contacts, i, preparation.inertia, s);
    }
    return deepest;
  });
}

namespace {

// solve_contact_once. Out of line, so that both sizes of solve_contact inline into it: inlined
// into the passes' loop instead, solve_contact<2> is not, and pyramid20 costs 3% more
// instructions (callgrind).
[[gnu::noinline]] double solve_once(ContactSet& contacts, const Contact& c,
                                    const BodyInertia& inertia, MotionState& s) {
  PairMotion m(c, inertia, s);
  const std::span<ContactPointState> points = contacts.points(c);
  const double impulse_change = c.count() == 1 ? solve_contact(contacts, c, points.first<1>(), m)
                                               : solve_contact(contacts, c, points.first<2>(), m);
  m.store(c, s);
  return impulse_change * (m.inverse_mass_a + m.inverse_mass_b);
}

}  // namespace

double solve_contact_once(ContactSet& contacts, const Contact& c, const BodyInertia& inertia,
                          MotionState& s) {
  return solve_once(contacts, c, inertia, s);
}

namespace {

// `pass(solve)` runs `solve` over the contacts, returning the largest value it returned.
template <typename Pass>
int solve_velocities_in(const Pass& pass, ContactSet& contacts, const BodyInertia& inertia,
                        int iterations, double tolerance, MotionState& s) {
  for (int i = 0; i < iterations;) {
    const double largest_change =
        pass([&](std::uint32_t k) { return solve_once(contacts, contacts[k], inertia, s); });
    ++i;
    // A pass that changed the velocities by at most the tolerance leaves the next about as
    // little to do (none at all when it changed nothing).
    if (largest_change <= tolerance) return i;
  }
  return iterations;
}

template <typename Order>
void apply_restitution_in(const Order& order, ContactSet& contacts, const BodyInertia& inertia,
                          MotionState& s) {
  if (!contacts.keeps_bounce_velocities()) return;
  order.run([&](std::uint32_t i) {
    const Contact& c = contacts[i];
    const std::span<const double> bounces = contacts.bounce_velocities(c);
    if (std::all_of(bounces.begin(), bounces.end(), [](double b) { return b == 0.0; })) {
      return 0.0;
    }
    PairMotion m(c, inertia, s);
    const std::span<ContactPointState> points = contacts.points(c);
    for (std::size_t k = 0; k < points.size(); ++k) {
      ContactPointState& p = points[k];
      if (bounces[k] == 0.0 || p.normal_impulse == 0.0) continue;
      const double change = -p.normal_mass * (m.normal_velocity(c, p) + bounces[k]);
      const double total = std::max(p.normal_impulse + change, 0.0);
      m.push_normal(c, p, total - p.normal_impulse);
      p.normal_impulse = total;
    }
    m.store(c, s);
    return 0.0;
  });
}

}  // namespace

int solve_velocities(ContactSet& contacts, const BodyInertia& inertia, int iterations,
                     double tolerance, MotionState& s) {
  const ContactsInOrder order(contacts);
  return solve_velocities_in([&](const auto& solve) { return order.run(solve); }, contacts, inertia,
                             iterations, tolerance, s);
}

namespace {

// One pass over contacts that share no movable body (a colour's, a level's), whose one-point
// contacts ContactBatches hands over first and its two-point ones after: each kind four at a time
// where the CPU has AVX2, else one by one. Returns the largest change.
double solve_independent(ContactSet& contacts, std::span<const std::uint32_t> independent,
                         const BodyInertia& inertia, MotionState& s) {
  const auto one_by_one = [&](std::span<const std::uint32_t> some) {
    double largest = 0.0;
    for (const std::uint32_t i : some) {
      largest = std::max(largest, solve_once(contacts, contacts[i], inertia, s));
    }
    return largest;
  };
  if (!four_lanes()) return one_by_one(independent);
  const auto single = independent.first(static_cast<std::size_t>(
      std::partition_point(independent.begin(), independent.end(),
                           [&](std::uint32_t i) { return contacts[i].count() == 1; }) -
      independent.begin()));
  const auto pairs = independent.subspan(single.size());
  // One contact alone is solved as fast one at a time.
  return std::max(
      single.size() > 1 ? solve_single_points(contacts, single, inertia, s) : one_by_one(single),
      pairs.size() > 1 ? solve_two_points(contacts, pairs, inertia, s) : one_by_one(pairs));
}

}  // namespace

int solve_velocities(const ContactBatches& batches, ContactSet& contacts,
                     const BodyInertia& inertia, const VelocityLimits& limits, MotionState& s) {
  return solve_velocities_in(
      [&](const auto& solve) {
        return batches.run(
            solve,
            [&](std::span<const std::uint32_t> independent) {
              return solve_independent(contacts, independent, inertia, s);
            },
            ContactBatches::Visit{.by_levels = true, .interleaved = true});
      },
      contacts, inertia, limits.iterations, limits.tolerance, s);
}

void apply_restitution(ContactSet& contacts, const BodyInertia& inertia, MotionState& s) {
  apply_restitution_in(ContactsInOrder(contacts), contacts, inertia, s);
}

void apply_restitution(const ContactBatches& batches, ContactSet& contacts,
                       const BodyInertia& inertia, MotionState& s) {
  apply_restitution_in(batches, contacts, inertia, s);
}

}  // namespace gp
