// The island's normal-impulse complementarity problem, on problems whose solution is known: a
// column of bodies by hand, and random contact problems built around a chosen solution.
#include <catch2/catch.hpp>
#include <random>

#include "engine/contacts/normal_lcp.hpp"

namespace {

constexpr double kGravity = 9.81;
constexpr double kStep = 1.0 / 60.0;

// The complementarity conditions of solve_normal_lcp, checked on its answer to 1e-9 of the
// problem's scales, for K with the compliance solve_normal_lcp documents (1e-10 of each diagonal
// entry, acting on the impulses' change).
void check_complementary(const Eigen::MatrixXd& k, const Eigen::VectorXd& w0,
                         const Eigen::VectorXd& start, const Eigen::VectorXd& impulse) {
  Eigen::MatrixXd compliant = k;
  compliant.diagonal() *= 1.0 + 1e-10;
  const Eigen::VectorXd w = w0 + compliant * (impulse - start);
  const double impulse_scale = std::max(impulse.maxCoeff(), start.maxCoeff());
  const double speed_scale = w0.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < w.size(); ++i) {
    CHECK(impulse(i) >= 0.0);
    CHECK(w(i) >= -1e-9 * speed_scale);
    CHECK(impulse(i) * w(i) <= 1e-9 * impulse_scale * speed_scale);
  }
}

}  // namespace

TEST_CASE(
    "A column of bodies at rest is solved in one round, each contact carrying the weight "
    "above it",
    "[GD:impulse][FR:Determine-Collision-Response-Over-Time]") {
  // Bodies 1..5 of masses m_j stacked on the ground, moving only vertically: point i lies under
  // body i+1. Gravity has given every body −g·h, so only the ground point closes (w₀ = −g·h);
  // the others move together (w₀ = 0). Each point must carry g·h times the mass above it.
  const std::vector<double> mass{2.0, 0.5, 7.0, 1.0, 3.0};
  const auto n = static_cast<Eigen::Index>(mass.size());
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    k(i, i) = 1.0 / mass[i] + (i > 0 ? 1.0 / mass[i - 1] : 0.0);
    if (i > 0) k(i, i - 1) = k(i - 1, i) = -1.0 / mass[i - 1];
  }
  Eigen::VectorXd w0 = Eigen::VectorXd::Zero(n);
  w0(0) = -kGravity * kStep;
  const Eigen::VectorXd start = Eigen::VectorXd::Zero(n);
  gp::NormalLcpScratch scratch;
  Eigen::VectorXd impulse(n);
  const gp::NormalLcpResult result = gp::solve_normal_lcp(k, w0, start, scratch, impulse);
  REQUIRE(result.solved);
  CHECK(result.rounds == 1);
  // The compliance of 1e-10 of each diagonal entry shifts the impulses by about 1e-10 times K's
  // condition number (about 50 here).
  double above = 0.0;
  for (Eigen::Index i = n - 1; i >= 0; --i) {
    above += mass[i];
    CHECK(impulse(i) == Approx(above * kGravity * kStep).epsilon(1e-8));
  }
}

TEST_CASE("Random heaps' contact problems are all solved, most within the engine's round limit",
          "[GD:impulse][FR:Determine-Collision-Response-Over-Time]") {
  // K = J M⁻¹ Jᵀ, as an island's effective-mass matrix is, for 2 to 4 points a body, each
  // between two random bodies or a body and the ground, with normals within 17° of upwards and
  // random arms; w₀ = J v for random velocities falling under a step of gravity; random warm
  // starts. The points outnumber the bodies' freedoms, so K is singular, and many such problems
  // ask for more than the bodies can give: the compliance keeps their solution unique, and large.
  // Block pivoting alone cycles for ever on some of them; with Murty's rule every one settles,
  // the slowest after 2090 rounds (at this writing; 27 on average).
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> positive(0.1, 1.0);
  int problems = 0;
  int within_limit = 0;
  for (int bodies : {4, 8, 16, 24}) {
    for (int points_per_body : {2, 3, 4}) {
      for (int trial = 0; trial < 20; ++trial) {
        const int n = bodies * points_per_body;
        Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(n, 3 * bodies);
        Eigen::VectorXd inverse_mass(3 * bodies);
        for (int b = 0; b < bodies; ++b) {
          const double m = 1.0 + 9.0 * positive(random);
          inverse_mass.segment(3 * b, 3) << 1.0 / m, 1.0 / m, 12.0 / m;
        }
        const auto moment_arm = [&](const Eigen::Vector2d& normal) {
          const Eigen::Vector2d arm(0.5 * unit(random), 0.5 * unit(random));
          return arm.x() * normal.y() - arm.y() * normal.x();
        };
        for (int i = 0; i < n; ++i) {
          const auto a = static_cast<int>(random() % bodies);
          const auto b = static_cast<int>(random() % (bodies + 1));  // bodies: the ground
          const Eigen::Vector2d normal = Eigen::Vector2d(0.3 * unit(random), 1.0).normalized();
          jacobian.block(i, 3 * a, 1, 2) = normal.transpose();
          jacobian(i, 3 * a + 2) = moment_arm(normal);
          if (b != a && b < bodies) {
            jacobian.block(i, 3 * b, 1, 2) = -normal.transpose();
            jacobian(i, 3 * b + 2) = -moment_arm(normal);
          }
        }
        const Eigen::MatrixXd k = jacobian * inverse_mass.asDiagonal() * jacobian.transpose();
        Eigen::VectorXd velocity(3 * bodies);
        for (int i = 0; i < 3 * bodies; ++i) {
          velocity(i) = 0.3 * unit(random) - (i % 3 == 1 ? kGravity * kStep : 0.0);
        }
        const Eigen::VectorXd w0 = jacobian * velocity;
        Eigen::VectorXd start(n);
        for (int i = 0; i < n; ++i) start(i) = random() % 3 == 0 ? 0.0 : 0.2 * positive(random);
        gp::NormalLcpScratch scratch;
        Eigen::VectorXd impulse(n);
        const gp::NormalLcpResult result =
            gp::solve_normal_lcp(k, w0, start, scratch, impulse, 5000);
        INFO(bodies << " bodies, " << n << " points, trial " << trial);
        REQUIRE(result.solved);
        check_complementary(k, w0, start, impulse);
        ++problems;
        within_limit += result.rounds <= gp::kNormalLcpMaxRounds;
      }
    }
  }
  CHECK(problems == 240);
  // 198 of them (82%) at this writing.
  CHECK(within_limit >= 0.75 * problems);
}
