#include "verification/oracle/contact/contact_modes.hpp"

#include <algorithm>
#include <cmath>

#include "verification/oracle/contact/body_coupling.hpp"
#include "verification/oracle/contact/lemke.hpp"

namespace gp::oracle {

namespace {

// Where a contact's variables sit in the LCP: its normal force, and for a contact whose friction
// is still undecided, f₊, f₋ and β.
struct Slots {
  Eigen::Index normal;
  Eigen::Index plus = -1;  // -1: no friction variables
};

}  // namespace

bool choose_contact_modes(const World& world, std::vector<ActiveContact>& contacts,
                          std::span<const ContactKinematics> kinematics,
                          std::span<const Vec2> linear, std::span<const double> angular,
                          double slip_tolerance) {
  const std::size_t m = contacts.size();
  std::vector<Slots> slots(m);
  Eigen::Index size = 0;
  for (std::size_t i = 0; i < m; ++i) {
    ActiveContact& c = contacts[i];
    if (c.friction == 0.0) {
      c.mode = ContactMode::Frictionless;
    } else if (std::abs(kinematics[i].slip) > slip_tolerance) {
      c.mode = ContactMode::Sliding;
      c.slip_sign = kinematics[i].slip > 0.0 ? 1 : -1;
    } else if (c.mode != ContactMode::Sliding || c.slip_sign == 0) {
      c.mode = ContactMode::Sticking;
    }
    slots[i].normal = size++;
  }
  for (std::size_t i = 0; i < m; ++i) {
    if (contacts[i].mode == ContactMode::Sticking) {
      slots[i].plus = size;
      size += 3;
    }
  }
  // Column directions: what each force variable pushes along; row measures: what each w reads.
  std::vector<BodyPairVector> push(static_cast<std::size_t>(size));
  std::vector<BodyPairVector> normal(m);
  std::vector<BodyPairVector> tangent(m);
  for (std::size_t i = 0; i < m; ++i) {
    const ActiveContact& c = contacts[i];
    normal[i] = along(c, kinematics[i].normal_row);
    tangent[i] = along(c, kinematics[i].tangent_row);
    push[slots[i].normal] = normal_push(c, kinematics[i]);
    if (slots[i].plus >= 0) {
      push[slots[i].plus] = tangent[i];
      BodyPairVector minus = tangent[i];
      minus.on_first = -minus.on_first;
      minus.on_second = -minus.on_second;
      push[slots[i].plus + 1] = minus;
      push[slots[i].plus + 2] = {c.first, c.second, Eigen::Vector3d::Zero(),
                                 Eigen::Vector3d::Zero()};  // β pushes nothing
    }
  }
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(size, size);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(size);
  for (std::size_t i = 0; i < m; ++i) {
    const Eigen::Index rn = slots[i].normal;
    q[rn] = kinematics[i].normal_row.bias + dot(normal[i], linear, angular);
    for (Eigen::Index k = 0; k < size; ++k) M(rn, k) = coupling(world, normal[i], push[k]);
    const Eigen::Index rp = slots[i].plus;
    if (rp < 0) continue;
    const double slip_rate = kinematics[i].tangent_row.bias + dot(tangent[i], linear, angular);
    q[rp] = slip_rate;
    q[rp + 1] = -slip_rate;
    for (Eigen::Index k = 0; k < size; ++k) {
      const double c = coupling(world, tangent[i], push[k]);
      M(rp, k) = c;
      M(rp + 1, k) = -c;
    }
    M(rp, rp + 2) = 1.0;
    M(rp + 1, rp + 2) = 1.0;
    M(rp + 2, rn) = contacts[i].friction;
    M(rp + 2, rp) = -1.0;
    M(rp + 2, rp + 1) = -1.0;
  }
  if (size == 0) return true;
  const auto z = solve_lcp(M, q);
  if (!z) return false;
  const Eigen::VectorXd w = M * *z + q;
  // Forces and accelerations below these fractions of the problem's own scales are round-off.
  const double force_scale = std::max(z->cwiseAbs().maxCoeff(), 1e-300);
  // Accelerations are judged against the applied ones too: two bodies falling together touch
  // with g̈ = 0 up to round-off, which must not count as separating.
  double applied = 0.0;
  for (const Vec2& a : linear) applied = std::max(applied, a.norm());
  const double rate_scale = std::max({q.cwiseAbs().maxCoeff(), applied, 1e-300});
  std::vector<ActiveContact> kept;
  for (std::size_t i = 0; i < m; ++i) {
    ActiveContact c = contacts[i];
    const double fn = (*z)[slots[i].normal];
    if (fn <= 1e-12 * force_scale && w[slots[i].normal] > 1e-9 * rate_scale) continue;
    if (slots[i].plus >= 0 && (*z)[slots[i].plus + 2] > 1e-12 * rate_scale) {
      // β > 0: the friction is at its limit and the contact starts to slip, against the force.
      c.mode = ContactMode::Sliding;
      c.slip_sign = (*z)[slots[i].plus + 1] > (*z)[slots[i].plus] ? 1 : -1;
    }
    kept.push_back(c);
  }
  contacts = std::move(kept);
  return true;
}

}  // namespace gp::oracle
