#include "engine/solver/single_point_lanes.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>

#if GP_LANES_AVX2
#include "engine/avx2_lanes.hpp"
#endif

namespace gp {

namespace {

#if GP_LANES_AVX2

// The kernel loads four doubles at a time from a point's first nine fields and from a contact's
// normal on: they must lie one after the other, a double apart.
template <std::size_t N>
constexpr bool one_after_another(const std::array<std::size_t, N>& offsets) {
  for (std::size_t k = 1; k < N; ++k) {
    if (offsets[k] != offsets[0] + k * sizeof(double)) return false;
  }
  return true;
}
static_assert(one_after_another(std::array{
    offsetof(ContactPointState, normal_impulse), offsetof(ContactPointState, tangent_impulse),
    offsetof(ContactPointState, target_normal_velocity), offsetof(ContactPointState, normal_mass),
    offsetof(ContactPointState, tangent_mass), offsetof(ContactPointState, normal_arm_a),
    offsetof(ContactPointState, normal_arm_b), offsetof(ContactPointState, tangent_arm_a),
    offsetof(ContactPointState, tangent_arm_b)}));
// The normal, the friction, and 8 bytes more of the contact, which the kernel loads and drops.
static_assert(one_after_another(std::array{offsetof(Contact, normal), offsetof(Contact, normal) + 8,
                                           offsetof(Contact, friction)}) &&
              offsetof(Contact, friction) + 2 * sizeof(double) <= sizeof(Contact));

// The points and bodies of four contacts, a lane each.
struct FourContacts {
  std::array<ContactPointState*, 4> point;
  std::array<BodyId, 4> a, b;
};

// Doubles k to k + 3 from `first` of each of four records, a field each.
[[gnu::target("avx2")]] inline FourFields columns(const std::array<const double*, 4>& first,
                                                  std::size_t k) {
  return transpose(_mm256_loadu_pd(first[0] + k), _mm256_loadu_pd(first[1] + k),
                   _mm256_loadu_pd(first[2] + k), _mm256_loadu_pd(first[3] + k));
}

// One body of each of four contacts: its velocity and inverse inertias.
struct FourBodies {
  Four velocity_x, velocity_y, angular_velocity, inverse_mass, inverse_moment;
};

// The bodies `ids` of state `s`, a lane each, with their inverse mass and moment.
[[gnu::target("avx2")]] inline FourBodies gather_bodies(const std::array<BodyId, 4>& ids,
                                                        const BodyInertia& inertia,
                                                        const MotionState& s) {
  FourBodies body;
  split(s.velocity[ids[0]], s.velocity[ids[1]], s.velocity[ids[2]], s.velocity[ids[3]],
        body.velocity_x, body.velocity_y);
  body.angular_velocity = gather(s.angular_velocity.data(), ids);
  body.inverse_mass = gather(inertia.inverse_mass.data(), ids);
  body.inverse_moment = gather(inertia.inverse_moment.data(), ids);
  return body;
}

// The two bodies of four contacts, as PairMotion holds one contact's.
struct FourPairs {
  FourBodies a, b;
};

// A direction d (the normal or the tangent) of four points, with their arms crossed with it.
struct FourDirections {
  Four x, y, arm_a, arm_b;
};

// PairMotion::velocity_along: (v_a − v_b)·d + ω_a arm_a − ω_b arm_b.
[[gnu::target("avx2")]] inline Four along(const FourPairs& m, const FourDirections& d) {
  const Four dot = _mm256_add_pd(_mm256_mul_pd(_mm256_sub_pd(m.a.velocity_x, m.b.velocity_x), d.x),
                                 _mm256_mul_pd(_mm256_sub_pd(m.a.velocity_y, m.b.velocity_y), d.y));
  return _mm256_sub_pd(_mm256_add_pd(dot, _mm256_mul_pd(m.a.angular_velocity, d.arm_a)),
                       _mm256_mul_pd(m.b.angular_velocity, d.arm_b));
}

// `value` − (−j d m) in the lanes of `lanes`, `value` in the others, from `minus_j` = −j, d and m:
// the share left out is masked to +0 first, and v − (+0) is v to the bit, where v − (−x) is v + x.
// No blend lies on the chain through the velocities then (several micro-ops on Intel's cores, one
// on Zen 4).
[[gnu::target("avx2")]] inline Four add_share(Four value, Four minus_j, Four along, Four inverse,
                                              Four lanes) {
  return _mm256_sub_pd(value,
                       _mm256_and_pd(_mm256_mul_pd(_mm256_mul_pd(minus_j, along), inverse), lanes));
}

// The impulse j (dx, dy) at an arm whose cross product with the direction is `arm`, added to
// `body` in the lanes of `lanes` (DD:impulseV, DD:torque), given as `minus_j` = −j. B takes −j:
// rounding is symmetric, so each of its sums is the same to the bit as its subtraction of A's
// share in PairMotion.
[[gnu::target("avx2")]] inline void take(FourBodies& body, Four dx, Four dy, Four arm, Four minus_j,
                                         Four lanes) {
  body.velocity_x = add_share(body.velocity_x, minus_j, dx, body.inverse_mass, lanes);
  body.velocity_y = add_share(body.velocity_y, minus_j, dy, body.inverse_mass, lanes);
  body.angular_velocity =
      add_share(body.angular_velocity, minus_j, arm, body.inverse_moment, lanes);
}

// PairMotion::push_along, in the lanes of `lanes` only: j d to A, −j d to B (TM:NewtonThirdLawMot).
[[gnu::target("avx2")]] inline void push(FourPairs& m, const FourDirections& d, Four j,
                                         Four lanes) {
  take(m.a, d.x, d.y, d.arm_a, _mm256_xor_pd(j, _mm256_set1_pd(-0.0)), lanes);
  take(m.b, d.x, d.y, d.arm_b, j, lanes);
}

// The lanes, as bits, where `body` is movable: its inverse mass and moment, both at least 0, sum
// to more than 0.
[[gnu::target("avx2")]] inline int movable_lanes(const FourBodies& body) {
  return _mm256_movemask_pd(_mm256_cmp_pd(_mm256_add_pd(body.inverse_mass, body.inverse_moment),
                                          _mm256_setzero_pd(), _CMP_GT_OQ));
}

// The velocities of `body` back into `s`, in the lanes whose bits `lanes` sets: the x and y lanes
// interleaved again, each body's stored as the 16 bytes of its Vec2.
[[gnu::target("avx2")]] inline void store_bodies(const FourBodies& body,
                                                 const std::array<BodyId, 4>& ids, int lanes,
                                                 MotionState& s) {
  Four first_two, last_two;
  join_xy(body.velocity_x, body.velocity_y, first_two, last_two);
  // Arrays, not std::array, which would drop the vector type's alignment attribute.
  const __m128d velocity[4] = {
      _mm256_castpd256_pd128(first_two), _mm256_extractf128_pd(first_two, 1),
      _mm256_castpd256_pd128(last_two), _mm256_extractf128_pd(last_two, 1)};
  const __m128d w01 = _mm256_castpd256_pd128(body.angular_velocity);
  const __m128d w23 = _mm256_extractf128_pd(body.angular_velocity, 1);
  const __m128d angular[4] = {w01, _mm_unpackhi_pd(w01, w01), w23, _mm_unpackhi_pd(w23, w23)};
  for (std::size_t l = 0; l < 4; ++l) {
    if (((lanes >> l) & 1) == 0) continue;
    _mm_storeu_pd(s.velocity[ids[l]].data(), velocity[l]);
    _mm_store_sd(&s.angular_velocity[ids[l]], angular[l]);
  }
}

// solve_contact_once over the n ≤ 4 one-point contacts `ids` of `set`, lane by lane: friction
// where it is above 0, then the normal constraint, and nothing where the contact is idle. The
// lanes past n take the first contact, to read only, and change nothing.
[[gnu::target("avx2")]] double solve_four(ContactSet& set, const std::uint32_t* ids, std::size_t n,
                                          const BodyInertia& inertia, MotionState& s) {
  const __m256i lanes = first_lanes(n);
  FourContacts four;
  std::array<const double*, 4> point_fields, contact_fields;
  for (std::size_t l = 0; l < 4; ++l) {
    const Contact& c = set[ids[l < n ? l : 0]];
    ContactPointState& p = set.points(c)[0];
    four.point[l] = &p;
    four.a[l] = c.body_a;
    four.b[l] = c.body_b;
    point_fields[l] = &p.normal_impulse;
    contact_fields[l] = c.normal.data();
  }
  const FourFields impulses_to_masses = columns(point_fields, 0);
  const Four normal_impulse = impulses_to_masses.field[0];
  const Four tangent_impulse = impulses_to_masses.field[1];
  const Four target = impulses_to_masses.field[2];
  const Four normal_mass = impulses_to_masses.field[3];
  const FourFields mass_and_arms = columns(point_fields, 4);
  const Four tangent_mass = mass_and_arms.field[0];
  const Four tangent_arm_b =
      _mm256_set_pd(point_fields[3][8], point_fields[2][8], point_fields[1][8], point_fields[0][8]);
  const FourFields normal_and_friction = columns(contact_fields, 0);
  const Four nx = normal_and_friction.field[0];
  const Four ny = normal_and_friction.field[1];
  const Four friction = normal_and_friction.field[2];
  const FourDirections normal{nx, ny, mass_and_arms.field[1], mass_and_arms.field[2]};
  // contact_tangent: (−n_y, n_x).
  const FourDirections tangent{_mm256_xor_pd(ny, _mm256_set1_pd(-0.0)), nx, mass_and_arms.field[3],
                               tangent_arm_b};
  FourPairs m{gather_bodies(four.a, inertia, s), gather_bodies(four.b, inertia, s)};

  const Four zero = _mm256_setzero_pd();
  // Not idle (solve_contact's idle): an impulse already, or a point closing faster than its target.
  const Four busy =
      _mm256_and_pd(_mm256_castsi256_pd(lanes),
                    _mm256_or_pd(_mm256_or_pd(_mm256_cmp_pd(normal_impulse, zero, _CMP_NEQ_UQ),
                                              _mm256_cmp_pd(tangent_impulse, zero, _CMP_NEQ_UQ)),
                                 _mm256_cmp_pd(along(m, normal), target, _CMP_LT_OQ)));
  const Four rubs = _mm256_and_pd(busy, _mm256_cmp_pd(friction, zero, _CMP_GT_OQ));

  const Four sign = _mm256_set1_pd(-0.0);
  const Four limit = _mm256_mul_pd(friction, normal_impulse);
  const Four tangent_change = _mm256_mul_pd(_mm256_xor_pd(tangent_mass, sign), along(m, tangent));
  // std::clamp(v, −limit, limit), which is std::min(std::max(v, −limit), limit).
  const Four tangent_total = min_of(
      max_of(_mm256_add_pd(tangent_impulse, tangent_change), _mm256_xor_pd(limit, sign)), limit);
  const Four tangent_step = _mm256_sub_pd(tangent_total, tangent_impulse);
  push(m, tangent, tangent_step, rubs);

  const Four normal_change = _mm256_mul_pd(normal_mass, _mm256_sub_pd(target, along(m, normal)));
  const Four normal_total = max_of(_mm256_add_pd(normal_impulse, normal_change), zero);
  const Four normal_step = _mm256_sub_pd(normal_total, normal_impulse);
  push(m, normal, normal_step, busy);

  alignas(32) std::array<double, 4> normal_out, tangent_out;
  _mm256_store_pd(normal_out.data(), where(busy, normal_impulse, normal_total));
  _mm256_store_pd(tangent_out.data(), where(rubs, tangent_impulse, tangent_total));
  for (std::size_t l = 0; l < n; ++l) {
    four.point[l]->normal_impulse = normal_out[l];
    four.point[l]->tangent_impulse = tangent_out[l];
  }
  const Four largest_step =
      max_of(max_of(zero, _mm256_and_pd(magnitude(tangent_step), rubs)), magnitude(normal_step));
  alignas(32) std::array<double, 4> change;
  _mm256_store_pd(
      change.data(),
      _mm256_and_pd(_mm256_mul_pd(largest_step, _mm256_add_pd(m.a.inverse_mass, m.b.inverse_mass)),
                    busy));
  // Only movable bodies are written, as PairMotion::store does: a static body may be in
  // contacts solved on other threads at the same time.
  const int first_n = (1 << n) - 1;
  store_bodies(m.a, four.a, movable_lanes(m.a) & first_n, s);
  store_bodies(m.b, four.b, movable_lanes(m.b) & first_n, s);
  double largest = 0.0;
  for (std::size_t l = 0; l < n; ++l) largest = std::max(largest, change[l]);
  return largest;
}

#endif

}  // namespace

double solve_single_points(ContactSet& set, std::span<const std::uint32_t> contacts,
                           const BodyInertia& inertia, MotionState& s) {
#if GP_LANES_AVX2
  double largest = 0.0;
  for (std::size_t done = 0; done < contacts.size(); done += 4) {
    largest =
        std::max(largest, solve_four(set, contacts.data() + done,
                                     std::min<std::size_t>(4, contacts.size() - done), inertia, s));
  }
  return largest;
#else
  (void)set;
  (void)contacts;
  (void)inertia;
  (void)s;
  throw std::logic_error("solve_single_points: four lanes need AVX2");
#endif
}

const char* single_points_name() {
  return four_lanes() ? "four at a time (AVX2)" : "one at a time";
}

}  // namespace gp
