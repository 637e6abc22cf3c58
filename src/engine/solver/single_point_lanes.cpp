#include "engine/solver/single_point_lanes.hpp"

#include <array>
#include <cstddef>

#include "engine/solver/contacts_in_fours.hpp"

#if GP_LANES_AVX2
#include "engine/solver/contact_lanes.hpp"
#endif

namespace gp {

namespace {

#if GP_LANES_AVX2

// solve_contact_once over the n ≤ 4 one-point contacts `ids` of `set`, lane by lane: friction
// where it is above 0, then the normal constraint, and nothing where the contact is idle. The
// lanes past n take the first contact, to read only, and change nothing.
[[gnu::target("avx2")]] double solve_four_single_points(ContactSet& set, const std::uint32_t* ids,
                                                        std::size_t n, const BodyInertia& inertia,
                                                        MotionState& s) {
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
  const FourFields normal_and_friction = columns(contact_fields, 0);
  const Four friction = normal_and_friction.field[2];
  const FourPoints p =
      load_points(point_fields, normal_and_friction.field[0], normal_and_friction.field[1]);
  FourPairs m{gather_bodies(four.a, inertia, s), gather_bodies(four.b, inertia, s)};

  const Four zero = _mm256_setzero_pd();
  const Four busy = _mm256_and_pd(_mm256_castsi256_pd(lanes), not_idle(m, p));
  const Four rubs = _mm256_and_pd(busy, _mm256_cmp_pd(friction, zero, _CMP_GT_OQ));
  Four tangent_total, normal_total;
  const Four tangent_step = rub(m, p, friction, rubs, tangent_total);
  const Four normal_step = press(m, p, busy, normal_total);

  store_impulses(four, 0, n, where(busy, p.normal_impulse, normal_total),
                 where(rubs, p.tangent_impulse, tangent_total));
  const Four largest_step =
      max_of(max_of(zero, _mm256_and_pd(magnitude(tangent_step), rubs)), magnitude(normal_step));
  return store_four(four, m, largest_step, busy, n, s);
}

// The kernel solve_in_fours runs: none in a build without AVX2.
constexpr FourContactsKernel kSinglePointsKernel = solve_four_single_points;
#else
constexpr FourContactsKernel kSinglePointsKernel = nullptr;
#endif

}  // namespace

double solve_single_points(ContactSet& set, std::span<const std::uint32_t> contacts,
                           const BodyInertia& inertia, MotionState& s) {
  return solve_in_fours<kSinglePointsKernel>("solve_single_points", set, contacts, inertia, s);
}

const char* contact_lanes_name() {
  return four_lanes() ? "four at a time (AVX2)" : "one at a time";
}

}  // namespace gp
