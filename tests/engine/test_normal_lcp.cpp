// The island's normal-impulse complementarity problem: a column of bodies and two points by hand,
// and random heap-like problems checked against the complementarity conditions themselves (the
// solution of the problem with its compliance is unique).
#include <catch2/catch.hpp>
#include <random>

#include "engine/solver/normal_lcp.hpp"

namespace {
namespace test_normal_lcp {

constexpr double kGravity = 9.81;
constexpr double kStep = 1.0 / 60.0;

// The complementarity conditions of solve_normal_lcp, checked on its answer to the 1e-10 of the
// problem's scales it documents, for K with its compliance (1e-10 of each diagonal entry, acting
// on the impulses' change): the largest impulse, and the largest speed of w₀ (and of an island at
// rest, of K_ii |λ_i − λ₀_i|).
template <typename Matrix>
void check_complementary(const Matrix& k, const Eigen::VectorXd& w0, const Eigen::VectorXd& start,
                         const Eigen::VectorXd& impulse, bool at_rest = false) {
  const Eigen::VectorXd change = impulse - start;
  const Eigen::VectorXd diagonal = k.diagonal();
  const Eigen::VectorXd w = w0 + k * change + 1e-10 * diagonal.cwiseProduct(change);
  const double impulse_scale = std::max(impulse.maxCoeff(), start.maxCoeff());
  double speed_scale = w0.cwiseAbs().maxCoeff();
  if (at_rest)
    speed_scale = std::max(speed_scale, diagonal.cwiseProduct(change).cwiseAbs().maxCoeff());
  for (Eigen::Index i = 0; i < w.size(); ++i) {
    CHECK(impulse(i) >= 0.0);
    CHECK(w(i) >= -1e-10 * speed_scale);
    CHECK(impulse(i) * w(i) <= 1e-10 * impulse_scale * speed_scale);
  }
}

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

TEST_CASE("A point that pushed but must let go takes a second round, and the round limit holds",
          "[via:GD:impulse]") {
  // Two points of independent unit masses (K = I): point 0 closes at 1 m/s, point 1 pushed last
  // step (λ₀ = 1) but now separates at 2 m/s. The first guess has both pushing, which would
  // pull point 1 (λ = −1); the second frees it: λ = (1, 0), and point 1 separates at
  // 2 − 1 m/s less the compliance's 1e-10 m/s.
  const Eigen::MatrixXd k = Eigen::MatrixXd::Identity(2, 2);
  const Eigen::VectorXd w0 = Eigen::Vector2d(-1.0, 2.0);
  const Eigen::VectorXd start = Eigen::Vector2d(0.0, 1.0);
  gp::NormalLcpScratch scratch;
  Eigen::VectorXd impulse(2);
  const gp::NormalLcpResult limited =
      gp::solve_normal_lcp(k, w0, start, scratch, impulse, {.max_rounds = 1});
  CHECK_FALSE(limited.solved);
  CHECK(limited.rounds == 1);
  const gp::NormalLcpResult result = gp::solve_normal_lcp(k, w0, start, scratch, impulse);
  REQUIRE(result.solved);
  CHECK(result.rounds == 2);
  CHECK(impulse(0) == Approx(1.0).epsilon(1e-9));
  CHECK(impulse(1) == 0.0);
}

TEST_CASE("No points is solved at once, and a point no body can move is not solved",
          "[via:GD:impulse]") {
  gp::NormalLcpScratch scratch;
  Eigen::VectorXd none(0);
  CHECK(gp::solve_normal_lcp(Eigen::MatrixXd(0, 0), none, none, scratch, none).solved);
  // K_00 = 0: a point between bodies that cannot move along its normal; closing, it has no
  // impulse that stops it.
  const Eigen::MatrixXd k = Eigen::Matrix2d{{0.0, 0.0}, {0.0, 1.0}};
  Eigen::VectorXd impulse(2);
  CHECK_FALSE(gp::solve_normal_lcp(k, Eigen::Vector2d(-1.0, -1.0), Eigen::Vector2d::Zero(), scratch,
                                   impulse)
                  .solved);
}

TEST_CASE(
    "Random heaps' contact problems are all solved, dense and sparse, most within the engine's "
    "round limit, and bordering a sparse factor gives what a new one does",
    "[via:GD:impulse][FR:Determine-Collision-Response-Over-Time]") {
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
  int within_limit = 0;
  int rounds = 0;  // of the sparse solves
  int factorisations = 0;
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
            gp::solve_normal_lcp(k, w0, start, scratch, impulse, {.max_rounds = 5000});
        INFO(bodies << " bodies, " << n << " points, trial " << trial);
        REQUIRE(result.solved);
        check_complementary(k, w0, start, impulse);
        // The sparse solve, in its fill-reducing order, meets the same conditions.
        gp::NormalLcpScratch sparse_scratch;
        Eigen::VectorXd sparse_impulse(n);
        const gp::NormalLcpResult sparse_result = gp::solve_normal_lcp(
            k.sparseView(), w0, start, sparse_scratch, sparse_impulse, {.max_rounds = 5000});
        REQUIRE(sparse_result.solved);
        check_complementary(k, w0, start, sparse_impulse);
        // Made with a new factor every round, the same solution, to round-off.
        Eigen::VectorXd refactored(n);
        const gp::NormalLcpResult refactored_result =
            gp::solve_normal_lcp(k.sparseView(), w0, start, sparse_scratch, refactored,
                                 {.max_rounds = 5000, .most_let_go = 0});
        REQUIRE(refactored_result.solved);
        CHECK(refactored_result.factorisations == refactored_result.rounds);
        // 3.8e-11 of the largest impulse at most, at this writing.
        CHECK((sparse_impulse - refactored).cwiseAbs().maxCoeff() <=
              1e-10 * refactored.cwiseAbs().maxCoeff());
        rounds += sparse_result.rounds;
        factorisations += sparse_result.factorisations;
        within_limit += result.rounds <= gp::kNormalLcpMaxRounds;
      }
    }
  }
  // 198 of the 240 (82%) at this writing.
  CHECK(within_limit >= 0.75 * 240);
  // Rounds that only let points go border the last factor: 3752 factorisations for 6403 rounds
  // at this writing.
  CHECK(factorisations <= 0.7 * rounds);
}

TEST_CASE(
    "A pyramid of 820 boxes at rest is solved in 3 rounds and 1 factorisation as one at rest, in 7 "
    "rounds without, the ground carrying its weight",
    "[via:GD:impulse][FR:Determine-Collision-Response-Over-Time]") {
  // Unit boxes (m = 1 kg, I = 1/6 kg·m²) in 40 rows, each box on two below, touching its
  // neighbours: two points on the ground or on each box below it, two on each side. Gravity has
  // given every box −g·h: only the ground's points close. The side points carry next to nothing
  // (marked unloaded), while the impulses below reach 40 boxes' weight and the compliance's speeds
  // with them.
  constexpr int kRows = 40;
  struct Point {
    int a, b;  // the bodies, b = −1 for the ground; the normal points from b to a
    Eigen::Vector2d at, normal;
  };
  std::vector<Point> points;
  std::vector<Eigen::Vector2d> centre;
  std::vector<std::vector<int>> box(kRows);
  for (int i = 0; i < kRows; ++i) {
    for (int j = 0; j < kRows - i; ++j) {
      box[i].push_back(static_cast<int>(centre.size()));
      centre.emplace_back(j + 0.5 * i, i + 0.5);
    }
  }
  const Eigen::Vector2d up(0.0, 1.0);
  const Eigen::Vector2d right(1.0, 0.0);
  for (int i = 0; i < kRows; ++i) {
    for (int j = 0; j < kRows - i; ++j) {
      const int b = box[i][j];
      const double x = centre[b].x();
      const auto y = static_cast<double>(i);
      if (i == 0) {
        points.push_back({b, -1, {x - 0.5, y}, up});
        points.push_back({b, -1, {x + 0.5, y}, up});
      } else {
        points.push_back({b, box[i - 1][j], {x - 0.5, y}, up});
        points.push_back({b, box[i - 1][j], {x, y}, up});
        points.push_back({b, box[i - 1][j + 1], {x, y}, up});
        points.push_back({b, box[i - 1][j + 1], {x + 0.5, y}, up});
      }
      if (j + 1 < kRows - i) {
        points.push_back({box[i][j + 1], b, {x + 0.5, y}, right});
        points.push_back({box[i][j + 1], b, {x + 0.5, y + 1.0}, right});
      }
    }
  }
  const auto n = static_cast<Eigen::Index>(points.size());
  const auto bodies = static_cast<Eigen::Index>(centre.size());
  // K = J M⁻¹ Jᵀ, a row of J per point: ±(n, r × n) for each body.
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index p = 0; p < n; ++p) {
    const Point& q = points[p];
    for (const auto& [body, sign] : {std::pair{q.a, 1.0}, std::pair{q.b, -1.0}}) {
      if (body < 0) continue;
      const Eigen::Vector2d r = q.at - centre[body];
      entries.emplace_back(p, 3 * body, sign * q.normal.x());
      entries.emplace_back(p, 3 * body + 1, sign * q.normal.y());
      entries.emplace_back(p, 3 * body + 2, sign * (r.x() * q.normal.y() - r.y() * q.normal.x()));
    }
  }
  Eigen::SparseMatrix<double> jacobian(n, 3 * bodies);
  jacobian.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd inverse_mass(3 * bodies);
  Eigen::VectorXd velocity = Eigen::VectorXd::Zero(3 * bodies);
  for (Eigen::Index b = 0; b < bodies; ++b) {
    inverse_mass.segment(3 * b, 3) << 1.0, 1.0, 6.0;
    velocity(3 * b + 1) = -kGravity * kStep;
  }
  const gp::SparseK k = jacobian * inverse_mass.asDiagonal() * jacobian.transpose();
  const Eigen::VectorXd w0 = jacobian * velocity;
  const Eigen::VectorXd start = Eigen::VectorXd::Zero(n);
  std::vector<std::uint8_t> unloaded(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) unloaded[p] = points[p].normal == right;
  const gp::IslandAtRest at_rest{unloaded};
  gp::NormalLcpScratch scratch;
  Eigen::VectorXd impulse(n);
  const gp::NormalLcpResult result =
      gp::solve_normal_lcp(k, w0, start, scratch, impulse, {.at_rest = &at_rest});
  REQUIRE(result.solved);
  CHECK(result.rounds <= 3);
  check_complementary(k, w0, start, impulse, true);
  // Its later rounds only let points go, and border the first round's factor. A new factor every
  // round gives the same motions, to round-off.
  CHECK(result.factorisations == 1);
  Eigen::VectorXd refactored(n);
  const gp::NormalLcpResult refactored_result = gp::solve_normal_lcp(
      k, w0, start, scratch, refactored, {.at_rest = &at_rest, .most_let_go = 0});
  REQUIRE(refactored_result.solved);
  CHECK(refactored_result.rounds == result.rounds);
  CHECK(refactored_result.factorisations == result.rounds);
  const Eigen::VectorXd moved_bordered =
      inverse_mass.asDiagonal() * (jacobian.transpose() * impulse);
  const Eigen::VectorXd moved_refactored =
      inverse_mass.asDiagonal() * (jacobian.transpose() * refactored);
  // 2.4e-14 g h at this writing (the impulses themselves differ by 2e-6 of the largest, where the
  // pile is statically indeterminate, as below).
  CHECK((moved_bordered - moved_refactored).cwiseAbs().maxCoeff() <= 2e-13 * kGravity * kStep);
  // The ground stops the whole pyramid: its impulses add up to the weight times h, less what the
  // compliance lets it sink (2.6e-8 of it, at this writing).
  double ground = 0.0;
  for (Eigen::Index p = 0; p < n; ++p) ground += points[p].b < 0 ? impulse(p) : 0.0;
  CHECK(ground == Approx(static_cast<double>(bodies) * kGravity * kStep).epsilon(1e-7));
  // Solved as any island, every touching point starting pushing and every free one held to 1e-10
  // of w₀: more rounds, and the same motion. (Not the same impulses: the pile is statically
  // indeterminate, and how two points under a box share its load changes its motion only through
  // the compliance: 4.7e-10 m/s apart at this writing.)
  Eigen::VectorXd plain(n);
  const gp::NormalLcpResult plain_result = gp::solve_normal_lcp(k, w0, start, scratch, plain);
  REQUIRE(plain_result.solved);
  CHECK(plain_result.rounds >= 5);
  check_complementary(k, w0, start, plain);
  const Eigen::VectorXd moved = inverse_mass.asDiagonal() * (jacobian.transpose() * impulse);
  const Eigen::VectorXd moved_plain = inverse_mass.asDiagonal() * (jacobian.transpose() * plain);
  CHECK((moved - moved_plain).cwiseAbs().maxCoeff() <= 1e-8 * kGravity * kStep);
}

}  // namespace test_normal_lcp
}  // namespace
