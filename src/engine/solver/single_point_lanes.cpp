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

// The fields packed, an array each.
enum Field : std::size_t {
  kNormalX,
  kNormalY,
  kFriction,
  kNormalImpulse,
  kTangentImpulse,
  kTarget,
  kNormalMass,
  kTangentMass,
  kNormalArmA,
  kNormalArmB,
  kTangentArmA,
  kTangentArmB,
  kInverseMassA,
  kInverseMassB,
  kInverseMomentA,
  kInverseMomentB,
  kFields
};

// The packed arrays, as the kernel reads and writes them.
struct Columns {
  double* fields;
  std::size_t stride;
  const BodyId* body_a;
  const BodyId* body_b;

  double* at(Field f, std::size_t entry) const { return fields + f * stride + entry; }
};

#if GP_LANES_AVX2

// Field f of the n ≤ 4 entries from `entry` on (the lanes `lanes`); 0 in the lanes past them,
// whose memory is not touched: it may be another thread's, or past the end.
[[gnu::target("avx2")]] inline Four load(const Columns& c, Field f, std::size_t entry,
                                         std::size_t n, __m256i lanes) {
  return n == 4 ? _mm256_loadu_pd(c.at(f, entry)) : _mm256_maskload_pd(c.at(f, entry), lanes);
}
[[gnu::target("avx2")]] inline void store(const Columns& c, Field f, std::size_t entry,
                                          std::size_t n, __m256i lanes, Four v) {
  if (n == 4) {
    _mm256_storeu_pd(c.at(f, entry), v);
  } else {
    _mm256_maskstore_pd(c.at(f, entry), lanes, v);
  }
}

// One body of each of four contacts: its velocity and inverse inertias.
struct FourBodies {
  Four velocity_x, velocity_y, angular_velocity, inverse_mass, inverse_moment;
};

// The bodies `ids` of state `s`, a lane each, with their inverse mass and moment.
[[gnu::target("avx2")]] inline FourBodies gather_bodies(const std::array<BodyId, 4>& ids,
                                                        Four inverse_mass, Four inverse_moment,
                                                        const MotionState& s) {
  FourBodies body;
  split(s.velocity[ids[0]], s.velocity[ids[1]], s.velocity[ids[2]], s.velocity[ids[3]],
        body.velocity_x, body.velocity_y);
  body.angular_velocity = gather(s.angular_velocity.data(), ids);
  body.inverse_mass = inverse_mass;
  body.inverse_moment = inverse_moment;
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

// The fields of the n ≤ 4 entries from `entry` on, in `lanes`.
struct FourEntries {
  const Columns& columns;
  std::size_t entry;
  std::size_t n;
  __m256i lanes;

  [[gnu::target("avx2")]] Four operator()(Field f) const {
    return load(columns, f, entry, n, lanes);
  }
};

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

// solve_contact_once over the n ≤ 4 packed one-point contacts from `entry` on, lane by lane:
// friction where it is above 0, then the normal constraint, and nothing where the contact is
// idle. The lanes past n take the first's bodies, to read only, and change nothing.
[[gnu::target("avx2")]] double solve_four(const Columns& c, std::size_t entry, std::size_t n,
                                          MotionState& s) {
  const __m256i lanes = first_lanes(n);
  const FourEntries field{c, entry, n, lanes};
  std::array<BodyId, 4> a, b;
  for (std::size_t l = 0; l < 4; ++l) {
    a[l] = c.body_a[entry + (l < n ? l : 0)];
    b[l] = c.body_b[entry + (l < n ? l : 0)];
  }
  const Four normal_impulse = field(kNormalImpulse);
  const Four tangent_impulse = field(kTangentImpulse);
  const Four target = field(kTarget);
  const Four normal_mass = field(kNormalMass);
  const Four tangent_mass = field(kTangentMass);
  const Four nx = field(kNormalX);
  const Four ny = field(kNormalY);
  const FourDirections normal{nx, ny, field(kNormalArmA), field(kNormalArmB)};
  // contact_tangent: (−n_y, n_x).
  const FourDirections tangent{_mm256_xor_pd(ny, _mm256_set1_pd(-0.0)), nx, field(kTangentArmA),
                               field(kTangentArmB)};
  const Four friction = field(kFriction);
  FourPairs m{gather_bodies(a, field(kInverseMassA), field(kInverseMomentA), s),
              gather_bodies(b, field(kInverseMassB), field(kInverseMomentB), s)};

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

  store(c, kNormalImpulse, entry, n, lanes, where(busy, normal_impulse, normal_total));
  store(c, kTangentImpulse, entry, n, lanes, where(rubs, tangent_impulse, tangent_total));
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
  store_bodies(m.a, a, movable_lanes(m.a) & first_n, s);
  store_bodies(m.b, b, movable_lanes(m.b) & first_n, s);
  double largest = 0.0;
  for (std::size_t l = 0; l < n; ++l) largest = std::max(largest, change[l]);
  return largest;
}

#endif

}  // namespace

void SinglePointLanes::pack(std::span<const std::uint32_t> entries, const ContactSet& set,
                            const BodyInertia& inertia) {
  const std::size_t count = entries.size();
  fields_.resize(kFields * count);
  contact_.assign(entries.begin(), entries.end());
  single_.resize(count);
  body_a_.resize(count);
  body_b_.resize(count);
  const Columns columns{fields_.data(), count, body_a_.data(), body_b_.data()};
  for (std::size_t e = 0; e < count; ++e) {
    const Contact& c = set[entries[e]];
    single_[e] = c.count() == 1 ? 1 : 0;
    body_a_[e] = c.body_a;
    body_b_[e] = c.body_b;
    if (single_[e] == 0) continue;
    const ContactPointState& p = set.points(c)[0];
    const auto put = [&](Field f, double value) { *columns.at(f, e) = value; };
    put(kNormalX, c.normal.x());
    put(kNormalY, c.normal.y());
    put(kFriction, c.friction);
    put(kNormalImpulse, p.normal_impulse);
    put(kTangentImpulse, p.tangent_impulse);
    put(kTarget, p.target_normal_velocity);
    put(kNormalMass, p.normal_mass);
    put(kTangentMass, p.tangent_mass);
    put(kNormalArmA, p.normal_arm_a);
    put(kNormalArmB, p.normal_arm_b);
    put(kTangentArmA, p.tangent_arm_a);
    put(kTangentArmB, p.tangent_arm_b);
    put(kInverseMassA, inertia.inverse_mass[c.body_a]);
    put(kInverseMassB, inertia.inverse_mass[c.body_b]);
    put(kInverseMomentA, inertia.inverse_moment[c.body_a]);
    put(kInverseMomentB, inertia.inverse_moment[c.body_b]);
  }
}

std::size_t SinglePointLanes::leading_single_points(std::size_t first, std::size_t count) const {
  std::size_t n = 0;
  while (n < count && single_[first + n] != 0) ++n;
  return n;
}

double SinglePointLanes::solve(std::size_t first, std::size_t count, MotionState& s) {
#if GP_LANES_AVX2
  const Columns columns{fields_.data(), contact_.size(), body_a_.data(), body_b_.data()};
  double largest = 0.0;
  for (std::size_t done = 0; done < count; done += 4) {
    largest = std::max(
        largest, solve_four(columns, first + done, std::min<std::size_t>(4, count - done), s));
  }
  return largest;
#else
  (void)first;
  (void)count;
  (void)s;
  throw std::logic_error("SinglePointLanes::solve: four lanes need AVX2");
#endif
}

void SinglePointLanes::unpack(ContactSet& set) const {
  const std::size_t count = contact_.size();
  for (std::size_t e = 0; e < count; ++e) {
    if (single_[e] == 0) continue;
    ContactPointState& p = set.points(set[contact_[e]])[0];
    p.normal_impulse = fields_[kNormalImpulse * count + e];
    p.tangent_impulse = fields_[kTangentImpulse * count + e];
  }
}

const char* SinglePointLanes::name() {
  return four_lanes() ? "four at a time (AVX2)" : "one at a time";
}

}  // namespace gp
