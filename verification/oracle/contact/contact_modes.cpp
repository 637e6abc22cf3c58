#include "verification/oracle/contact/contact_modes.hpp"

#include <algorithm>
#include <cmath>

#include "verification/oracle/contact/friction_lcp.hpp"
#include "verification/oracle/contact/lemke.hpp"

namespace gp::oracle {

bool choose_contact_modes(const World& world, std::vector<ActiveContact>& contacts,
                          std::span<const ContactKinematics> kinematics,
                          std::span<const Vec2> linear, std::span<const double> angular,
                          double slip_tolerance) {
  const std::size_t m = contacts.size();
  std::vector<FrictionRow> rows;
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
    const ContactKinematics& k = kinematics[i];
    const BodyPairVector normal = along(c, k.normal_row);
    const BodyPairVector tangent = along(c, k.tangent_row);
    rows.push_back({normal, normal_push(c, k), tangent,
                    k.normal_row.bias + dot(normal, linear, angular),
                    k.tangent_row.bias + dot(tangent, linear, angular), c.friction,
                    c.mode == ContactMode::Sticking});
  }
  if (m == 0) return true;
  const FrictionLcp lcp = friction_lcp(world, rows);
  const auto z = solve_lcp(lcp.M, lcp.q);
  if (!z) return false;
  const Eigen::VectorXd w = lcp.M * *z + lcp.q;
  // Forces and accelerations below these fractions of the problem's own scales are round-off.
  const double force_scale = std::max(z->cwiseAbs().maxCoeff(), 1e-300);
  // Accelerations are judged against the applied ones too: two bodies falling together touch
  // with g̈ = 0 up to round-off, which must not count as separating.
  double applied = 0.0;
  for (const Vec2& a : linear) applied = std::max(applied, a.norm());
  const double rate_scale = std::max({lcp.q.cwiseAbs().maxCoeff(), applied, 1e-300});
  std::vector<ActiveContact> kept;
  for (std::size_t i = 0; i < m; ++i) {
    ActiveContact c = contacts[i];
    const double fn = (*z)[lcp.slots[i].normal];
    if (fn <= 1e-12 * force_scale && w[lcp.slots[i].normal] > 1e-9 * rate_scale) continue;
    if (lcp.slots[i].plus >= 0 && (*z)[lcp.slots[i].plus + 2] > 1e-12 * rate_scale) {
      // β > 0: the friction is at its limit and the contact starts to slip, against the force.
      c.mode = ContactMode::Sliding;
      c.slip_sign = (*z)[lcp.slots[i].plus + 1] > (*z)[lcp.slots[i].plus] ? 1 : -1;
    }
    kept.push_back(c);
  }
  contacts = std::move(kept);
  return true;
}

}  // namespace gp::oracle
