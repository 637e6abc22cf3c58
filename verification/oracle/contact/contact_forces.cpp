#include "verification/oracle/contact/contact_forces.hpp"

#include <Eigen/QR>

#include "verification/oracle/contact/body_coupling.hpp"

namespace gp::oracle {

namespace {

// One unknown force magnitude: the direction it pushes in, the row it holds at zero and where it
// goes in the result.
struct Unknown {
  BodyPairVector direction;
  BodyPairVector constraint;
  double bias;
  std::size_t contact;
  bool tangential;
};

std::vector<Unknown> unknowns_of(std::span<const ActiveContact> contacts,
                                 std::span<const ContactKinematics> kinematics) {
  std::vector<Unknown> unknowns;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const ActiveContact& c = contacts[i];
    const ContactKinematics& k = kinematics[i];
    // A sliding contact's normal force carries its friction.
    unknowns.push_back({normal_push(c, k), along(c, k.normal_row), k.normal_row.bias, i, false});
    if (c.mode == ContactMode::Sticking) {
      const BodyPairVector t = along(c, k.tangent_row);
      unknowns.push_back({t, t, k.tangent_row.bias, i, true});
    }
  }
  return unknowns;
}

}  // namespace

std::vector<ContactForce> solve_contact_forces(const World& world,
                                               std::span<const ActiveContact> contacts,
                                               std::span<const ContactKinematics> kinematics,
                                               std::span<Vec2> linear, std::span<double> angular) {
  std::vector<ContactForce> forces(contacts.size(), ContactForce{0.0, 0.0, true});
  const std::vector<Unknown> unknowns = unknowns_of(contacts, kinematics);
  const auto n = static_cast<Eigen::Index>(unknowns.size());
  if (n == 0) return forces;
  Eigen::MatrixXd a(n, n);
  Eigen::VectorXd rhs(n);
  for (Eigen::Index r = 0; r < n; ++r) {
    const Unknown& row = unknowns[r];
    rhs[r] = -(row.bias + dot(row.constraint, linear, angular));
    for (Eigen::Index k = 0; k < n; ++k) {
      a(r, k) = coupling(world, row.constraint, unknowns[k].direction);
    }
  }
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> solver;
  // Redundant contacts make the matrix singular in exact arithmetic; in floating point their
  // singular values are round-off of its largest, which this threshold treats as zero.
  solver.setThreshold(1e-10);
  solver.compute(a);
  const Eigen::VectorXd lambda = solver.solve(rhs);
  const bool unique = solver.rank() == n;
  for (Eigen::Index k = 0; k < n; ++k) {
    const Unknown& u = unknowns[k];
    add_response(world, u.direction, lambda[k], linear, angular);
    ContactForce& f = forces[u.contact];
    f.unique = unique;
    if (u.tangential) {
      f.tangent = lambda[k];
    } else {
      f.normal = lambda[k];
      if (contacts[u.contact].mode == ContactMode::Sliding) {
        f.tangent = -contacts[u.contact].friction * contacts[u.contact].slip_sign * lambda[k];
      }
    }
  }
  return forces;
}

}  // namespace gp::oracle
