#include "verification/oracle/contact/projection.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <vector>

#include "verification/oracle/contact/body_coupling.hpp"
#include "verification/oracle/contact/contact_kinematics.hpp"

namespace gp::oracle {

namespace {

// m: a gap this small is round-off of the positions (1e-16 relative at 10 m).
constexpr double kConverged = 1e-15;

// The least M-weighted change Δ with rows·Δ = −values: Δ = M⁻¹ Jᵀ (J M⁻¹ Jᵀ)⁺ (−values).
void least_change(const World& world, const std::vector<BodyPairVector>& rows,
                  const std::vector<double>& values, std::span<Vec2> linear,
                  std::span<double> angular) {
  const auto n = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXd a(n, n);
  Eigen::VectorXd rhs(n);
  for (Eigen::Index r = 0; r < n; ++r) {
    rhs[r] = -values[r];
    for (Eigen::Index k = 0; k < n; ++k) a(r, k) = coupling(world, rows[r], rows[k]);
  }
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> solver;
  solver.setThreshold(1e-10);  // as in contact_forces.cpp: redundant contacts
  solver.compute(a);
  const Eigen::VectorXd lambda = solver.solve(rhs);
  for (Eigen::Index k = 0; k < n; ++k) add_response(world, rows[k], lambda[k], linear, angular);
}

}  // namespace

double project_positions(const World& world, std::span<const ActiveContact> contacts,
                         std::span<Motion> motions) {
  std::vector<Vec2> linear(motions.size());
  std::vector<double> angular(motions.size());
  std::vector<BodyPairVector> rows;
  std::vector<double> values;
  double largest = 0.0;
  // Newton on the gaps; quadratic convergence takes 1e-9 m to round-off in two iterations.
  for (int iteration = 0; iteration < 4; ++iteration) {
    const std::vector<ContactKinematics> k = kinematics_of(contacts, motions);
    rows.clear();
    values.clear();
    largest = 0.0;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      rows.push_back(along(contacts[i], k[i].normal_row));
      values.push_back(k[i].gap);
      largest = std::max(largest, std::abs(k[i].gap));
    }
    if (largest <= kConverged) break;
    std::fill(linear.begin(), linear.end(), Vec2::Zero());
    std::fill(angular.begin(), angular.end(), 0.0);
    least_change(world, rows, values, linear, angular);
    for (std::size_t b = 0; b < motions.size(); ++b) {
      motions[b].position += linear[b];
      motions[b].angle += angular[b];
    }
  }
  largest = 0.0;
  for (const ContactKinematics& ki : kinematics_of(contacts, motions)) {
    largest = std::max(largest, std::abs(ki.gap));
  }
  return largest;
}

double project_onto_contacts(const World& world, std::span<const ActiveContact> contacts,
                             std::span<Motion> motions) {
  if (contacts.empty()) return 0.0;
  project_positions(world, contacts, motions);
  const std::vector<ContactKinematics> k = kinematics_of(contacts, motions);
  std::vector<BodyPairVector> rows;
  std::vector<double> values;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    rows.push_back(along(contacts[i], k[i].normal_row));
    values.push_back(k[i].gap_rate);
    if (contacts[i].mode == ContactMode::Sticking) {
      rows.push_back(along(contacts[i], k[i].tangent_row));
      values.push_back(k[i].slip);
    }
  }
  std::vector<Vec2> linear(motions.size(), Vec2::Zero());
  std::vector<double> angular(motions.size(), 0.0);
  least_change(world, rows, values, linear, angular);
  for (std::size_t b = 0; b < motions.size(); ++b) {
    motions[b].velocity += linear[b];
    motions[b].angular_velocity += angular[b];
  }
  double largest = 0.0;
  for (const ContactKinematics& ki : kinematics_of(contacts, motions)) {
    largest = std::max(largest, std::abs(ki.gap));
  }
  return largest;
}

}  // namespace gp::oracle
