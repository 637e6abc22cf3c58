#pragma once
// What the kernels that solve a colour's or a level's contacts four at a time share (one-point
// contacts: single_point_lanes, two-point ones: two_point_lanes): a field of four contacts, points
// or bodies in one 256-bit register, and the pushes of PairMotion lane by lane. Include it only
// under GP_LANES_AVX2 (engine/lanes.hpp); its functions are compiled for AVX2 alone.

#include <array>
#include <cstddef>

#include "engine/avx2_lanes.hpp"
#include "engine/solver/contact_set.hpp"

namespace gp {

// The kernels load four doubles at a time from a point's first nine fields and from a contact's
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

// The points (the first of each) and bodies of four contacts, a lane each.
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

// What a pass reads of one point of each of four contacts: its impulses, target and effective
// masses, and its normal and tangent with its arms crossed with them.
struct FourPoints {
  Four normal_impulse, tangent_impulse, target, normal_mass, tangent_mass;
  FourDirections normal, tangent;
};

// The points whose fields start at `first` (their normal_impulse), of contacts whose normals are
// (nx, ny), a lane each.
[[gnu::target("avx2")]] inline FourPoints load_points(const std::array<const double*, 4>& first,
                                                      Four nx, Four ny) {
  const FourFields impulses_to_masses = columns(first, 0);
  const FourFields mass_and_arms = columns(first, 4);
  const Four tangent_arm_b = _mm256_set_pd(first[3][8], first[2][8], first[1][8], first[0][8]);
  FourPoints p;
  p.normal_impulse = impulses_to_masses.field[0];
  p.tangent_impulse = impulses_to_masses.field[1];
  p.target = impulses_to_masses.field[2];
  p.normal_mass = impulses_to_masses.field[3];
  p.tangent_mass = mass_and_arms.field[0];
  p.normal = FourDirections{nx, ny, mass_and_arms.field[1], mass_and_arms.field[2]};
  // contact_tangent: (−n_y, n_x).
  p.tangent = FourDirections{_mm256_xor_pd(ny, _mm256_set1_pd(-0.0)), nx, mass_and_arms.field[3],
                             tangent_arm_b};
  return p;
}

// Whether a pass over a point changes nothing (solve_contact's idle): no impulse yet, and the
// point separates at least as fast as its target. All ones in the lanes where it is not idle.
[[gnu::target("avx2")]] inline Four not_idle(const FourPairs& m, const FourPoints& p) {
  const Four zero = _mm256_setzero_pd();
  return _mm256_or_pd(_mm256_or_pd(_mm256_cmp_pd(p.normal_impulse, zero, _CMP_NEQ_UQ),
                                   _mm256_cmp_pd(p.tangent_impulse, zero, _CMP_NEQ_UQ)),
                      _mm256_cmp_pd(along(m, p.normal), p.target, _CMP_LT_OQ));
}

// solve_contact's friction at point `p`, in the lanes of `lanes`: the accumulated tangent impulse
// clamped to the cone of the normal one (friction μ), into `total`. Returns its change.
[[gnu::target("avx2")]] inline Four rub(FourPairs& m, const FourPoints& p, Four friction,
                                        Four lanes, Four& total) {
  const Four sign = _mm256_set1_pd(-0.0);
  const Four limit = _mm256_mul_pd(friction, p.normal_impulse);
  const Four change = _mm256_mul_pd(_mm256_xor_pd(p.tangent_mass, sign), along(m, p.tangent));
  // std::clamp(v, −limit, limit), which is std::min(std::max(v, −limit), limit).
  total =
      min_of(max_of(_mm256_add_pd(p.tangent_impulse, change), _mm256_xor_pd(limit, sign)), limit);
  const Four step = _mm256_sub_pd(total, p.tangent_impulse);
  push(m, p.tangent, step, lanes);
  return step;
}

// solve_contact's normal constraint at point `p` alone, in the lanes of `lanes`: the accumulated
// normal impulse that drives v_rel·n to the target, kept at least 0, into `total`. Returns its
// change.
[[gnu::target("avx2")]] inline Four press(FourPairs& m, const FourPoints& p, Four lanes,
                                          Four& total) {
  const Four change = _mm256_mul_pd(p.normal_mass, _mm256_sub_pd(p.target, along(m, p.normal)));
  total = max_of(_mm256_add_pd(p.normal_impulse, change), _mm256_setzero_pd());
  const Four step = _mm256_sub_pd(total, p.normal_impulse);
  push(m, p.normal, step, lanes);
  return step;
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

// The normal and tangent impulses of four points, a lane each, into point k of the first n of
// `contacts`: each point's two with one 16-byte store, as they lie side by side.
[[gnu::target("avx2")]] inline void store_impulses(const FourContacts& contacts, std::size_t k,
                                                   std::size_t n, Four normal, Four tangent) {
  const Four even = _mm256_unpacklo_pd(normal, tangent);  // (n0, t0, n2, t2)
  const Four odd = _mm256_unpackhi_pd(normal, tangent);   // (n1, t1, n3, t3)
  // Arrays, not std::array, which would drop the vector type's alignment attribute.
  const __m128d pairs[4] = {_mm256_castpd256_pd128(even), _mm256_castpd256_pd128(odd),
                            _mm256_extractf128_pd(even, 1), _mm256_extractf128_pd(odd, 1)};
  for (std::size_t l = 0; l < n; ++l) {
    _mm_storeu_pd(&contacts.point[l][k].normal_impulse, pairs[l]);
  }
}

// The end of a pass over four contacts, lane by lane as solve_contact_once ends: the velocities of
// `m` back into `s` for the first n lanes' movable bodies (as PairMotion::store: a static body may
// be in contacts solved on other threads at the same time), and the largest of the lanes' largest
// impulse change `largest_step` times the sum of their inverse masses, 0 where not `busy`.
[[gnu::target("avx2")]] inline double store_four(const FourContacts& four, const FourPairs& m,
                                                 Four largest_step, Four busy, std::size_t n,
                                                 MotionState& s) {
  const Four change = _mm256_and_pd(
      _mm256_mul_pd(largest_step, _mm256_add_pd(m.a.inverse_mass, m.b.inverse_mass)), busy);
  const int first_n = (1 << n) - 1;
  store_bodies(m.a, four.a, movable_lanes(m.a) & first_n, s);
  store_bodies(m.b, four.b, movable_lanes(m.b) & first_n, s);
  // std::max(largest, change) from 0 in the lanes' order, each as _mm_max_sd(change, largest):
  // the lanes past n, not busy, hold +0 and leave it as it is.
  const __m128d low = _mm256_castpd256_pd128(change);
  const __m128d high = _mm256_extractf128_pd(change, 1);
  __m128d largest = _mm_max_sd(low, _mm_setzero_pd());
  largest = _mm_max_sd(_mm_unpackhi_pd(low, low), largest);
  largest = _mm_max_sd(high, largest);
  largest = _mm_max_sd(_mm_unpackhi_pd(high, high), largest);
  return _mm_cvtsd_f64(largest);
}

}  // namespace gp
