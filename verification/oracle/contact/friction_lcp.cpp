#include "verification/oracle/contact/friction_lcp.hpp"

namespace gp::oracle {

FrictionLcp friction_lcp(const World& world, std::span<const FrictionRow> rows) {
  FrictionLcp lcp;
  const std::size_t m = rows.size();
  lcp.slots.resize(m);
  Eigen::Index size = 0;
  for (std::size_t i = 0; i < m; ++i) lcp.slots[i].normal = size++;
  for (std::size_t i = 0; i < m; ++i) {
    if (rows[i].undecided) {
      lcp.slots[i].plus = size;
      size += 3;
    }
  }
  lcp.push.resize(static_cast<std::size_t>(size));
  for (std::size_t i = 0; i < m; ++i) {
    const FrictionRow& r = rows[i];
    lcp.push[lcp.slots[i].normal] = r.normal_push;
    const Eigen::Index p = lcp.slots[i].plus;
    if (p < 0) continue;
    lcp.push[p] = r.tangent;
    lcp.push[p + 1] = {r.tangent.first, r.tangent.second, -r.tangent.on_first,
                       -r.tangent.on_second};
    lcp.push[p + 2] = {r.tangent.first, r.tangent.second, Eigen::Vector3d::Zero(),
                       Eigen::Vector3d::Zero()};
  }
  lcp.M = Eigen::MatrixXd::Zero(size, size);
  lcp.q = Eigen::VectorXd::Zero(size);
  for (std::size_t i = 0; i < m; ++i) {
    const FrictionRow& r = rows[i];
    const Eigen::Index rn = lcp.slots[i].normal;
    lcp.q[rn] = r.normal_rate;
    for (Eigen::Index k = 0; k < size; ++k) lcp.M(rn, k) = coupling(world, r.normal, lcp.push[k]);
    const Eigen::Index rp = lcp.slots[i].plus;
    if (rp < 0) continue;
    lcp.q[rp] = r.slip_rate;
    lcp.q[rp + 1] = -r.slip_rate;
    for (Eigen::Index k = 0; k < size; ++k) {
      const double c = coupling(world, r.tangent, lcp.push[k]);
      lcp.M(rp, k) = c;
      lcp.M(rp + 1, k) = -c;
    }
    lcp.M(rp, rp + 2) = 1.0;
    lcp.M(rp + 1, rp + 2) = 1.0;
    lcp.M(rp + 2, rn) = r.friction;
    lcp.M(rp + 2, rp) = -1.0;
    lcp.M(rp + 2, rp + 1) = -1.0;
  }
  return lcp;
}

}  // namespace gp::oracle
