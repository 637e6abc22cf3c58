#include "engine/solver/single_point_lanes.hpp"

#include <algorithm>
#include <array>
#include <cstddef>

#include "engine/solver/velocity_passes.hpp"

#if GP_LANES_AVX2
#include "engine/avx2_lanes.hpp"
#endif

namespace gp {

namespace {

#if GP_LANES_AVX2

// The four 256-bit loads of a point's fields read them in this order.
static_assert(offsetof(ContactPointState, tangent_impulse) == 8 &&
              offsetof(ContactPointState, target_normal_velocity) == 16 &&
              offsetof(ContactPointState, normal_mass) == 24 &&
              offsetof(ContactPointState, tangent_mass) == 32 &&
              offsetof(ContactPointState, normal_arm_a) == 40 &&
              offsetof(ContactPointState, normal_arm_b) == 48 &&
              offsetof(ContactPointState, tangent_arm_a) == 56);

using Four = __m256d;

// Four fields of four points, a field in each (a struct: std::array would drop the alignment
// attribute of the vector type).
struct FourFields {
  Four first, second, third, fourth;
};

// The four consecutive fields from `field` on of each of the points `p`: a row of each point
// loaded, then the rows transposed.
[[gnu::target("avx2")]] inline FourFields fields_from(const std::array<ContactPointState*, 4>& p,
                                                      double ContactPointState::*field) {
  const Four r0 = _mm256_loadu_pd(&(p[0]->*field));
  const Four r1 = _mm256_loadu_pd(&(p[1]->*field));
  const Four r2 = _mm256_loadu_pd(&(p[2]->*field));
  const Four r3 = _mm256_loadu_pd(&(p[3]->*field));
  const Four t0 = _mm256_unpacklo_pd(r0, r1);
  const Four t1 = _mm256_unpackhi_pd(r0, r1);
  const Four t2 = _mm256_unpacklo_pd(r2, r3);
  const Four t3 = _mm256_unpackhi_pd(r2, r3);
  return {_mm256_permute2f128_pd(t0, t2, 0x20), _mm256_permute2f128_pd(t1, t3, 0x20),
          _mm256_permute2f128_pd(t0, t2, 0x31), _mm256_permute2f128_pd(t1, t3, 0x31)};
}

// Four vectors, anywhere, into their x and y lanes.
[[gnu::target("avx2")]] inline void split(const Vec2& v0, const Vec2& v1, const Vec2& v2,
                                          const Vec2& v3, Four& x, Four& y) {
  split_xy(_mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(v0.data())),
                                _mm_loadu_pd(v1.data()), 1),
           _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(v2.data())),
                                _mm_loadu_pd(v3.data()), 1),
           x, y);
}

[[gnu::target("avx2")]] inline Four gather(const double* values, const std::array<BodyId, 4>& b) {
  return _mm256_set_pd(values[b[3]], values[b[2]], values[b[1]], values[b[0]]);
}

// std::max(a, b) and std::min(a, b) lane by lane, equal values and NaN included: each gives its
// first argument unless the second is larger (smaller), where the instructions give their second
// operand unless the first is.
[[gnu::target("avx2")]] inline Four max_of(Four a, Four b) {
  return _mm256_max_pd(b, a);
}
[[gnu::target("avx2")]] inline Four min_of(Four a, Four b) {
  return _mm256_min_pd(b, a);
}
[[gnu::target("avx2")]] inline Four magnitude(Four x) {
  return _mm256_andnot_pd(_mm256_set1_pd(-0.0), x);
}

// One body of each of four contacts: its velocity and inverse inertias.
struct FourBodies {
  Four velocity_x, velocity_y, angular_velocity, inverse_mass, inverse_moment;
};

// The bodies `ids` of state `s`, a lane each.
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

// `after` in the lanes of `mask`, `before` in the others.
[[gnu::target("avx2")]] inline Four where(Four mask, Four before, Four after) {
  return _mm256_blendv_pd(before, after, mask);
}

// The impulse j (dx, dy) at an arm whose cross product with the direction is `arm`, added to
// `body` in the lanes of `lanes` (DD:impulseV, DD:torque). B takes −j: rounding is symmetric, so
// each of its sums is the same to the bit as its subtraction of A's share in PairMotion.
[[gnu::target("avx2")]] inline void take(FourBodies& body, Four dx, Four dy, Four arm, Four j,
                                         Four lanes) {
  const Four turn = _mm256_mul_pd(_mm256_mul_pd(j, arm), body.inverse_moment);
  body.velocity_x =
      where(lanes, body.velocity_x,
            _mm256_add_pd(body.velocity_x, _mm256_mul_pd(_mm256_mul_pd(j, dx), body.inverse_mass)));
  body.velocity_y =
      where(lanes, body.velocity_y,
            _mm256_add_pd(body.velocity_y, _mm256_mul_pd(_mm256_mul_pd(j, dy), body.inverse_mass)));
  body.angular_velocity =
      where(lanes, body.angular_velocity, _mm256_add_pd(body.angular_velocity, turn));
}

// PairMotion::push_along, in the lanes of `lanes` only: j d to A, −j d to B (TM:NewtonThirdLawMot).
[[gnu::target("avx2")]] inline void push(FourPairs& m, const FourDirections& d, Four j,
                                         Four lanes) {
  take(m.a, d.x, d.y, d.arm_a, j, lanes);
  take(m.b, d.x, d.y, d.arm_b, _mm256_xor_pd(j, _mm256_set1_pd(-0.0)), lanes);
}

// solve_contact_once over the one-point contacts `four`, lane by lane: friction where it is above
// 0, then the normal constraint, and nothing where the contact is idle.
[[gnu::target("avx2")]] double solve_four(ContactSet& set, const std::uint32_t* four,
                                          const BodyInertia& inertia, MotionState& s) {
  const std::array<const Contact*, 4> c{&set[four[0]], &set[four[1]], &set[four[2]], &set[four[3]]};
  const std::array<ContactPointState*, 4> p{&set.points(*c[0])[0], &set.points(*c[1])[0],
                                            &set.points(*c[2])[0], &set.points(*c[3])[0]};
  const auto [normal_impulse, tangent_impulse, target, normal_mass] =
      fields_from(p, &ContactPointState::normal_impulse);
  const auto [tangent_mass, normal_arm_a, normal_arm_b, tangent_arm_a] =
      fields_from(p, &ContactPointState::tangent_mass);
  const Four tangent_arm_b = _mm256_set_pd(p[3]->tangent_arm_b, p[2]->tangent_arm_b,
                                           p[1]->tangent_arm_b, p[0]->tangent_arm_b);
  Four nx, ny;
  split(c[0]->normal, c[1]->normal, c[2]->normal, c[3]->normal, nx, ny);
  const FourDirections normal{nx, ny, normal_arm_a, normal_arm_b};
  // contact_tangent: (−n_y, n_x).
  const FourDirections tangent{_mm256_xor_pd(ny, _mm256_set1_pd(-0.0)), nx, tangent_arm_a,
                               tangent_arm_b};
  const Four friction =
      _mm256_set_pd(c[3]->friction, c[2]->friction, c[1]->friction, c[0]->friction);
  const std::array<BodyId, 4> a{c[0]->body_a, c[1]->body_a, c[2]->body_a, c[3]->body_a};
  const std::array<BodyId, 4> b{c[0]->body_b, c[1]->body_b, c[2]->body_b, c[3]->body_b};
  FourPairs m{gather_bodies(a, inertia, s), gather_bodies(b, inertia, s)};

  const Four zero = _mm256_setzero_pd();
  // Not idle (solve_contact's idle): an impulse already, or a point closing faster than its target.
  const Four busy = _mm256_or_pd(_mm256_or_pd(_mm256_cmp_pd(normal_impulse, zero, _CMP_NEQ_UQ),
                                              _mm256_cmp_pd(tangent_impulse, zero, _CMP_NEQ_UQ)),
                                 _mm256_cmp_pd(along(m, normal), target, _CMP_LT_OQ));
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

  const Four largest_step =
      max_of(max_of(zero, _mm256_and_pd(magnitude(tangent_step), rubs)), magnitude(normal_step));
  alignas(32) std::array<double, 4> change, normal_out, tangent_out, vax, vay, wa, vbx, vby, wb;
  _mm256_store_pd(
      change.data(),
      _mm256_and_pd(_mm256_mul_pd(largest_step, _mm256_add_pd(m.a.inverse_mass, m.b.inverse_mass)),
                    busy));
  _mm256_store_pd(normal_out.data(), where(busy, normal_impulse, normal_total));
  _mm256_store_pd(tangent_out.data(), where(rubs, tangent_impulse, tangent_total));
  _mm256_store_pd(vax.data(), m.a.velocity_x);
  _mm256_store_pd(vay.data(), m.a.velocity_y);
  _mm256_store_pd(wa.data(), m.a.angular_velocity);
  _mm256_store_pd(vbx.data(), m.b.velocity_x);
  _mm256_store_pd(vby.data(), m.b.velocity_y);
  _mm256_store_pd(wb.data(), m.b.angular_velocity);
  double largest = 0.0;
  for (std::size_t l = 0; l < 4; ++l) {
    p[l]->normal_impulse = normal_out[l];
    p[l]->tangent_impulse = tangent_out[l];
    // Only movable bodies are written, as PairMotion::store does: a static body may be in
    // contacts solved on other threads at the same time.
    if (inertia.inverse_mass[a[l]] + inertia.inverse_moment[a[l]] > 0.0) {
      s.velocity[a[l]] = Vec2(vax[l], vay[l]);
      s.angular_velocity[a[l]] = wa[l];
    }
    if (inertia.inverse_mass[b[l]] + inertia.inverse_moment[b[l]] > 0.0) {
      s.velocity[b[l]] = Vec2(vbx[l], vby[l]);
      s.angular_velocity[b[l]] = wb[l];
    }
    largest = std::max(largest, change[l]);
  }
  return largest;
}

#endif

}  // namespace

double solve_single_points(ContactSet& set, std::span<const std::uint32_t> contacts,
                           const BodyInertia& inertia, MotionState& s, Lanes lanes) {
  double largest = 0.0;
  std::size_t done = 0;
#if GP_LANES_AVX2
  if (lanes == Lanes::kFour) {
    for (; done + 4 <= contacts.size(); done += 4) {
      largest = std::max(largest, solve_four(set, contacts.data() + done, inertia, s));
    }
  }
#endif
  for (; done < contacts.size(); ++done) {
    largest = std::max(largest, solve_contact_once(set, set[contacts[done]], inertia, s));
  }
  return largest;
}

const char* single_point_lanes_name(Lanes lanes) {
  return lanes == Lanes::kFour && GP_LANES_AVX2 ? "four at a time (AVX2)" : "one at a time";
}

}  // namespace gp
