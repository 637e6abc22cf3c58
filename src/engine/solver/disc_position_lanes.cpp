#include "engine/solver/disc_position_lanes.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "engine/solver/contact_islands.hpp"
#include "gamephysics/models/dd/angular_displacement.hpp"

#if GP_LANES_AVX2
#include "engine/avx2_lanes.hpp"
#endif

namespace gp {

namespace {

#if GP_LANES_AVX2

// The n ≤ 4 contacts from `four` on, a lane each: PositionCorrection's pass over a point whose
// anchors are both centred discs (arms along the normal, no moment). Every lane's separation is
// found: a point the pass one at a time passes over as surely within the slop (its bound leaves
// room for the separation's round-off many times over) has no excess here either, and so is left
// as it is. The lanes past n take the first's contact, to read only.
[[gnu::target("avx2")]] bool correct_four(const ContactSet& set, const std::uint32_t* four,
                                          std::size_t n, const DiscPositionInput& in,
                                          MotionState& s) {
  std::array<const Contact*, 4> c;
  std::array<const ContactPointState*, 4> p;
  std::array<BodyId, 4> a, b;
  for (std::size_t l = 0; l < 4; ++l) {
    c[l] = &set[four[l < n ? l : 0]];
    p[l] = &set.points(*c[l])[0];
    a[l] = c[l]->body_a;
    b[l] = c[l]->body_b;
  }
  const auto point_field = [&p](double ContactPointState::*field) {
    return std::array<double, 4>{p[0]->*field, p[1]->*field, p[2]->*field, p[3]->*field};
  };
  Four nx, ny, pax, pay, pbx, pby;
  split(c[0]->normal, c[1]->normal, c[2]->normal, c[3]->normal, nx, ny);
  split(s.position[a[0]], s.position[a[1]], s.position[a[2]], s.position[a[3]], pax, pay);
  split(s.position[b[0]], s.position[b[1]], s.position[b[2]], s.position[b[3]], pbx, pby);
  const Four depth = _mm256_set_pd(p[3]->depth, p[2]->depth, p[1]->depth, p[0]->depth);
  const Four tangent_arm_a = _mm256_loadu_pd(point_field(&ContactPointState::tangent_arm_a).data());
  const Four tangent_arm_b = _mm256_loadu_pd(point_field(&ContactPointState::tangent_arm_b).data());
  const Four normal_mass = _mm256_loadu_pd(point_field(&ContactPointState::normal_mass).data());
  const Four slop = _mm256_set1_pd(in.slop);
  const Four zero = _mm256_setzero_pd();
  const Four sign = _mm256_set1_pd(-0.0);

  // The deepest points, half the depth from the contact point along the normal.
  const Four half_depth = _mm256_mul_pd(_mm256_set1_pd(0.5), depth);
  const Four reach_a = _mm256_sub_pd(half_depth, tangent_arm_a);
  const Four reach_b = _mm256_add_pd(tangent_arm_b, half_depth);
  const Four arm_ax = _mm256_mul_pd(reach_a, _mm256_xor_pd(nx, sign));
  const Four arm_ay = _mm256_mul_pd(reach_a, _mm256_xor_pd(ny, sign));
  const Four arm_bx = _mm256_mul_pd(reach_b, nx);
  const Four arm_by = _mm256_mul_pd(reach_b, ny);
  const Four gap_x = _mm256_sub_pd(_mm256_sub_pd(_mm256_add_pd(pax, arm_ax), pbx), arm_bx);
  const Four gap_y = _mm256_sub_pd(_mm256_sub_pd(_mm256_add_pd(pay, arm_ay), pby), arm_by);
  const Four separation = _mm256_add_pd(_mm256_mul_pd(gap_x, nx), _mm256_mul_pd(gap_y, ny));
  const Four excess =
      min_of(max_of(_mm256_mul_pd(_mm256_set1_pd(0.2), _mm256_add_pd(separation, slop)),
                    _mm256_set1_pd(-0.2)),
             zero);
  const Four acts =
      _mm256_and_pd(_mm256_castsi256_pd(first_lanes(n)), _mm256_cmp_pd(excess, zero, _CMP_NEQ_UQ));
  const Four deep = _mm256_and_pd(
      acts, _mm256_cmp_pd(separation, _mm256_mul_pd(_mm256_set1_pd(-2.0), slop), _CMP_LT_OQ));

  // displace: A by shift / m_A, B by −shift / m_B.
  const Four push = _mm256_mul_pd(_mm256_xor_pd(excess, sign), normal_mass);
  const Four shift_x = _mm256_mul_pd(push, nx);
  const Four shift_y = _mm256_mul_pd(push, ny);
  const Four inverse_mass_a = gather(in.inertia.inverse_mass.data(), a);
  const Four inverse_mass_b = gather(in.inertia.inverse_mass.data(), b);
  alignas(32) std::array<double, 4> ax, ay, bx, by;
  _mm256_store_pd(ax.data(), _mm256_add_pd(pax, _mm256_mul_pd(shift_x, inverse_mass_a)));
  _mm256_store_pd(ay.data(), _mm256_add_pd(pay, _mm256_mul_pd(shift_y, inverse_mass_a)));
  _mm256_store_pd(bx.data(),
                  _mm256_add_pd(pbx, _mm256_mul_pd(_mm256_xor_pd(shift_x, sign), inverse_mass_b)));
  _mm256_store_pd(by.data(),
                  _mm256_add_pd(pby, _mm256_mul_pd(_mm256_xor_pd(shift_y, sign), inverse_mass_b)));
  const int acting = _mm256_movemask_pd(acts);
  const BodyInertia& m = in.inertia;
  for (std::size_t l = 0; l < n; ++l) {
    if (((acting >> l) & 1) == 0) continue;
    // Only movable bodies are written: a static one may be in contacts on other threads. A turn
    // of 0 · I⁻¹ leaves the angle as dd::rotated_orientation gives it, in [0, 2π).
    if (movable(m, a[l])) {
      s.position[a[l]] = Vec2(ax[l], ay[l]);
      s.angle[a[l]] = dd::rotated_orientation(s.angle[a[l]], 0.0 * m.inverse_moment[a[l]]);
    }
    if (movable(m, b[l])) {
      s.position[b[l]] = Vec2(bx[l], by[l]);
      s.angle[b[l]] = dd::rotated_orientation(s.angle[b[l]], 0.0 * m.inverse_moment[b[l]]);
    }
  }
  return _mm256_movemask_pd(deep) != 0;
}

#endif

}  // namespace

bool correct_centred_discs(const ContactSet& set, std::span<const std::uint32_t> contacts,
                           const DiscPositionInput& in, MotionState& s) {
#if GP_LANES_AVX2
  bool deep = false;
  for (std::size_t done = 0; done < contacts.size(); done += 4) {
    deep = correct_four(set, contacts.data() + done,
                        std::min<std::size_t>(4, contacts.size() - done), in, s) ||
           deep;
  }
  return deep;
#else
  (void)set;
  (void)contacts;
  (void)in;
  (void)s;
  throw std::logic_error("correct_centred_discs: four lanes need AVX2");
#endif
}

}  // namespace gp
