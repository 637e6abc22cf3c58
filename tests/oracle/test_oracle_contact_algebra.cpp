// The oracle's contact algebra against independent references: Lemke's method against the
// complementarity conditions it must satisfy, and a contact's exact second derivatives against
// central finite differences of its own gap and slip along analytic motions.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "verification/oracle/contact/contact_kinematics.hpp"
#include "verification/oracle/contact/lemke.hpp"

using gp::Vec2;
using gp::oracle::ActiveContact;
using gp::oracle::contact_kinematics;
using gp::oracle::Motion;
using gp::oracle::solve_lcp;

TEST_CASE("Lemke's method solves a hand-worked LCP", "[oracle][lcp]") {
  // w = M z + q with M = [[2, 1], [1, 2]], q = (−5, 6): z₂ = 0 (w₂ = z₁ + 6 > 0), z₁ = 2.5.
  Eigen::MatrixXd M(2, 2);
  M << 2, 1, 1, 2;
  const auto z = solve_lcp(M, Eigen::Vector2d(-5, 6));
  REQUIRE(z);
  CHECK((*z)[0] == Approx(2.5).epsilon(1e-15));
  CHECK((*z)[1] == 0.0);
}

TEST_CASE("Lemke's method satisfies complementarity on random positive semidefinite LCPs",
          "[oracle][lcp]") {
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + trial % 24;
    // Rank-deficient half the time: redundant contacts make singular Delassus matrices.
    const int rank = trial % 2 ? n : std::max(1, n / 2);
    Eigen::MatrixXd A(rank, n);
    for (int i = 0; i < rank; ++i) {
      for (int j = 0; j < n; ++j) A(i, j) = normal(random);
    }
    const Eigen::MatrixXd M = A.transpose() * A;
    // q in the range of M minus a positive part, so that a solution exists.
    Eigen::VectorXd x(n), q(n);
    for (int i = 0; i < n; ++i) x[i] = std::abs(normal(random));
    for (int i = 0; i < n; ++i) q[i] = std::abs(normal(random));
    q -= M * x;
    const auto z = solve_lcp(M, q);
    REQUIRE(z);
    const Eigen::VectorXd w = M * *z + q;
    const double scale = q.cwiseAbs().maxCoeff() + M.cwiseAbs().maxCoeff() * z->maxCoeff();
    INFO("trial " << trial << ", n " << n << ", rank " << rank);
    CHECK(z->minCoeff() >= 0.0);
    CHECK(w.minCoeff() >= -1e-10 * scale);
    CHECK(std::abs(w.dot(*z)) <= 1e-10 * scale * std::max(1.0, z->sum()));
  }
}

namespace {
namespace test_oracle_contact_algebra {

// A motion under constant accelerations, advanced by h exactly.
Motion advanced(const Motion& m, const Vec2& a, double alpha, double h) {
  return {m.position + h * m.velocity + 0.5 * h * h * a,
          m.angle + h * m.angular_velocity + 0.5 * h * h * alpha, m.velocity + h * a,
          m.angular_velocity + h * alpha};
}

void check_derivatives(const ActiveContact& c, const Motion& m1, const Motion& m2,
                       std::mt19937& random) {
  std::normal_distribution<double> normal;
  const Vec2 a1(normal(random), normal(random)), a2(normal(random), normal(random));
  const double alpha1 = normal(random), alpha2 = normal(random);
  const auto k = contact_kinematics(c, m1, m2);
  const double h = 1e-5;
  const auto at = [&](double dt) {
    return contact_kinematics(c, advanced(m1, a1, alpha1, dt), advanced(m2, a2, alpha2, dt));
  };
  const auto plus = at(h), minus = at(-h);
  const Eigen::Vector3d acc1(a1.x(), a1.y(), alpha1), acc2(a2.x(), a2.y(), alpha2);
  const double gap_acceleration =
      k.normal_row.first.dot(acc1) + k.normal_row.second.dot(acc2) + k.normal_row.bias;
  const double slip_rate =
      k.tangent_row.first.dot(acc1) + k.tangent_row.second.dot(acc2) + k.tangent_row.bias;
  // Central differences are second order: with derivatives of order 1 and h = 1e-5 their error
  // is about 1e-10, well above round-off (1e-16 / 1e-5 = 1e-11).
  CHECK((plus.gap - minus.gap) / (2 * h) == Approx(k.gap_rate).margin(1e-8));
  CHECK((plus.gap_rate - minus.gap_rate) / (2 * h) == Approx(gap_acceleration).margin(1e-8));
  CHECK((plus.slip - minus.slip) / (2 * h) == Approx(slip_rate).margin(1e-8));
}

TEST_CASE("a contact's gap and slip accelerations match finite differences of its motion",
          "[oracle][contact]") {
  std::mt19937 random(11);
  std::normal_distribution<double> normal;
  const auto motion = [&] {
    return Motion{Vec2(normal(random), normal(random)), normal(random),
                  Vec2(normal(random), normal(random)), normal(random)};
  };
  for (int trial = 0; trial < 100; ++trial) {
    ActiveContact c{};
    c.first = 0;
    c.second = 1;
    c.vertex = {normal(random), normal(random)};
    c.anchor = {normal(random), normal(random)};
    c.first_radius = trial % 3 == 0 ? 0.0 : 0.3;
    c.radius = c.first_radius + (trial % 2 ? 0.2 : 0.0);
    c.on_edge = trial % 2 == 0;
    if (c.on_edge) {
      c.edge_end = c.anchor + Vec2(normal(random), normal(random));
      const Vec2 d = c.edge_end - c.anchor;
      c.edge_normal = Vec2(d.y(), -d.x()).normalized();
    }
    INFO("trial " << trial << (c.on_edge ? ", vertex on edge" : ", vertex on vertex"));
    check_derivatives(c, motion(), motion(), random);
  }
}

}  // namespace test_oracle_contact_algebra
}  // namespace
