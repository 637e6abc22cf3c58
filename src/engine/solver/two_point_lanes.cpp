#include "engine/solver/two_point_lanes.hpp"

#include <array>
#include <cstddef>

#include "engine/solver/contacts_in_fours.hpp"

#if GP_LANES_AVX2
#include "engine/solver/contact_lanes.hpp"
#endif

namespace gp {

namespace {

#if GP_LANES_AVX2

// The kernel loads a block's entries four doubles at a time, from k11 and from k22.
static_assert(one_after_another(std::array{
    offsetof(NormalBlock, k11), offsetof(NormalBlock, k12), offsetof(NormalBlock, k22),
    offsetof(NormalBlock, inverse11), offsetof(NormalBlock, inverse12),
    offsetof(NormalBlock, inverse22)}));

// The lanes where x ≥ 0 (false for NaN, as the comparison in C++).
[[gnu::target("avx2")]] inline Four at_least_0(Four x) {
  return _mm256_cmp_pd(x, _mm256_setzero_pd(), _CMP_GE_OQ);
}

// The normal impulses of a block solve: solve_pair's first case that holds, lane by lane, and the
// lanes where one holds.
struct BlockImpulses {
  Four first, second;
  Four holds;
};

// solve_pair's four cases, from b, the velocities the two constraints must reach less what the
// impulses already applied give: both points push (x = −K⁻¹ b), only the first, only the second,
// neither. `block` holds k11, k12, k22 and inverse11; `inverse`, from k22 on, inverse12 and
// inverse22 in its fields 2 and 3.
[[gnu::target("avx2")]] inline BlockImpulses block_cases(const FourFields& block,
                                                         const FourFields& inverse,
                                                         const FourPoints& p, const FourPoints& q,
                                                         Four bx, Four by) {
  const Four zero = _mm256_setzero_pd();
  const Four sign = _mm256_set1_pd(-0.0);
  const Four k12 = block.field[1];
  const Four inverse11 = block.field[3];
  const Four inverse12 = inverse.field[2];
  const Four inverse22 = inverse.field[3];
  const Four both_x = _mm256_xor_pd(
      _mm256_add_pd(_mm256_mul_pd(inverse11, bx), _mm256_mul_pd(inverse12, by)), sign);
  const Four both_y = _mm256_xor_pd(
      _mm256_add_pd(_mm256_mul_pd(inverse12, bx), _mm256_mul_pd(inverse22, by)), sign);
  const Four both = _mm256_and_pd(at_least_0(both_x), at_least_0(both_y));
  const Four first_x = _mm256_mul_pd(_mm256_xor_pd(bx, sign), p.normal_mass);
  const Four first = _mm256_and_pd(at_least_0(first_x),
                                   at_least_0(_mm256_add_pd(_mm256_mul_pd(k12, first_x), by)));
  const Four second_y = _mm256_mul_pd(_mm256_xor_pd(by, sign), q.normal_mass);
  const Four second = _mm256_and_pd(at_least_0(second_y),
                                    at_least_0(_mm256_add_pd(_mm256_mul_pd(k12, second_y), bx)));
  const Four neither = _mm256_and_pd(at_least_0(bx), at_least_0(by));
  // The first case that holds: +0 for a point that does not push, as in solve_pair.
  BlockImpulses x;
  x.first = where(both, where(first, zero, first_x), both_x);
  x.second = where(both, where(first, where(second, zero, second_y), zero), both_y);
  // A block with no inverse (inverse11 = 0) is not solvable.
  x.holds = _mm256_and_pd(_mm256_cmp_pd(inverse11, zero, _CMP_GT_OQ),
                          _mm256_or_pd(_mm256_or_pd(both, first), _mm256_or_pd(second, neither)));
  return x;
}

// solve_contact_once over the n ≤ 4 two-point contacts `ids` of `set`, lane by lane: friction at
// each point where it is above 0, then both normal constraints by the block where it serves, else
// one after the other, and nothing where the contact is idle. The lanes past n take the first
// contact, to read only, and change nothing.
[[gnu::target("avx2")]] double solve_four_two_points(ContactSet& set, const std::uint32_t* ids,
                                                     std::size_t n, const BodyInertia& inertia,
                                                     MotionState& s) {
  const __m256i lanes = first_lanes(n);
  FourContacts four;
  std::array<const double*, 4> first_fields, second_fields, contact_fields, block_fields;
  for (std::size_t l = 0; l < 4; ++l) {
    const Contact& c = set[ids[l < n ? l : 0]];
    const std::span<ContactPointState> points = set.points(c);
    four.point[l] = points.data();
    four.a[l] = c.body_a;
    four.b[l] = c.body_b;
    first_fields[l] = &points[0].normal_impulse;
    second_fields[l] = &points[1].normal_impulse;
    contact_fields[l] = c.normal.data();
    block_fields[l] = &set.block(c).k11;
  }
  const FourFields normal_and_friction = columns(contact_fields, 0);
  const Four nx = normal_and_friction.field[0];
  const Four ny = normal_and_friction.field[1];
  const Four friction = normal_and_friction.field[2];
  const FourPoints p = load_points(first_fields, nx, ny);
  const FourPoints q = load_points(second_fields, nx, ny);
  const FourFields block = columns(block_fields, 0);
  const FourFields inverse = columns(block_fields, 2);
  FourPairs m{gather_bodies(four.a, inertia, s), gather_bodies(four.b, inertia, s)};

  const Four zero = _mm256_setzero_pd();
  const Four busy =
      _mm256_and_pd(_mm256_castsi256_pd(lanes), _mm256_or_pd(not_idle(m, p), not_idle(m, q)));
  const Four rubs = _mm256_and_pd(busy, _mm256_cmp_pd(friction, zero, _CMP_GT_OQ));
  Four tangent_p, tangent_q;
  const Four rub_p = rub(m, p, friction, rubs, tangent_p);
  const Four rub_q = rub(m, q, friction, rubs, tangent_q);
  const Four rubbed = max_of(max_of(zero, _mm256_and_pd(magnitude(rub_p), rubs)),
                             _mm256_and_pd(magnitude(rub_q), rubs));

  // solve_pair: b = v_rel·n − target − K λ_old at each point.
  const Four k11 = block.field[0];
  const Four k12 = block.field[1];
  const Four k22 = block.field[2];
  const Four bx = _mm256_sub_pd(
      _mm256_sub_pd(along(m, p.normal), p.target),
      _mm256_add_pd(_mm256_mul_pd(k11, p.normal_impulse), _mm256_mul_pd(k12, q.normal_impulse)));
  const Four by = _mm256_sub_pd(
      _mm256_sub_pd(along(m, q.normal), q.target),
      _mm256_add_pd(_mm256_mul_pd(k12, p.normal_impulse), _mm256_mul_pd(k22, q.normal_impulse)));
  const BlockImpulses x = block_cases(block, inverse, p, q, bx, by);
  const Four by_block = _mm256_and_pd(busy, x.holds);
  const Four block_step_p = _mm256_sub_pd(x.first, p.normal_impulse);
  const Four block_step_q = _mm256_sub_pd(x.second, q.normal_impulse);
  push(m, p.normal, block_step_p, by_block);
  push(m, q.normal, block_step_q, by_block);
  // Where the block does not serve, the points one after the other, from the velocities the
  // block's lanes left alone.
  const Four one_by_one = _mm256_andnot_pd(x.holds, busy);
  Four pressed_p, pressed_q;
  const Four press_step_p = press(m, p, one_by_one, pressed_p);
  const Four press_step_q = press(m, q, one_by_one, pressed_q);

  const Four normal_p = where(by_block, where(one_by_one, p.normal_impulse, pressed_p), x.first);
  const Four normal_q = where(by_block, where(one_by_one, q.normal_impulse, pressed_q), x.second);
  store_impulses(four, 0, n, normal_p, where(rubs, p.tangent_impulse, tangent_p));
  store_impulses(four, 1, n, normal_q, where(rubs, q.tangent_impulse, tangent_q));
  const Four largest_step =
      where(by_block, max_of(max_of(rubbed, magnitude(press_step_p)), magnitude(press_step_q)),
            max_of(max_of(rubbed, magnitude(block_step_p)), magnitude(block_step_q)));
  return store_four(four, m, largest_step, busy, n, s);
}

// The kernel solve_in_fours runs: none in a build without AVX2.
constexpr FourContactsKernel kTwoPointsKernel = solve_four_two_points;
#else
constexpr FourContactsKernel kTwoPointsKernel = nullptr;
#endif

}  // namespace

double solve_two_points(ContactSet& set, std::span<const std::uint32_t> contacts,
                        const BodyInertia& inertia, MotionState& s) {
  return solve_in_fours<kTwoPointsKernel>("solve_two_points", set, contacts, inertia, s);
}

}  // namespace gp
