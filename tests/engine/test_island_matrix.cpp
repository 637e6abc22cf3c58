// The sparse effective-mass matrix of a large island (assemble_sparse), built column by column
// from the points' ends on each body, against the entries the dense one takes, each computed on
// its own from the two points' contacts (normal_coupling).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <vector>

#include <tbb/task_arena.h>

#include "engine/solver/contact_set.hpp"
#include "engine/solver/island_solver.hpp"
#include "engine/solver/velocity_passes.hpp"

namespace {
namespace test_island_matrix {

TEST_CASE(
    "A large island's sparse K holds normal_coupling's entry wherever two points share a "
    "moving body, and nothing else",
    "[FR:Determine-Collision-Response-Over-Time]") {
  // Body 0 is static; bodies 1 to 4 have unequal masses and moments [1/kg, 1/(kg·m²)].
  const gp::BodyInertia inertia{{0.0, 1.0, 0.5, 0.25, 2.0}, {0.0, 6.0, 3.0, 1.5, 0.7}};
  // Contacts of one and two points: two between bodies 2 and 1 (as two shapes of a body make),
  // and two on the static body, whose points share no moving body.
  struct Made {
    gp::BodyId a, b;
    int points;
    double normal_angle;  // rad
  };
  const std::vector<Made> made{{1, 0, 2, 1.5}, {2, 1, 2, 0.3}, {2, 1, 1, 2.0}, {3, 2, 1, -0.7},
                               {4, 3, 2, 0.9}, {4, 1, 1, 2.8}, {3, 0, 1, 1.1}};
  gp::ContactSet contacts;
  gp::IslandScratch scratch;
  double arm = 0.1;  // m, a different arm for every point
  for (std::uint32_t i = 0; i < made.size(); ++i) {
    gp::Contact& c = contacts.append(made[i].points);
    c.body_a = made[i].a;
    c.body_b = made[i].b;
    c.normal = {std::cos(made[i].normal_angle), std::sin(made[i].normal_angle)};
    for (std::uint32_t k = 0; k < static_cast<std::uint32_t>(made[i].points); ++k) {
      gp::set_arms(contacts.points(c)[k], c.normal, {arm, 0.3 - arm}, {-0.2 * arm, arm + 0.4});
      arm += 0.137;
      scratch.rows.push_back({i, k});
    }
  }
  gp::assemble_sparse(contacts, inertia, scratch);
  const auto n = static_cast<Eigen::Index>(scratch.rows.size());
  REQUIRE(scratch.k_sparse.rows() == n);
  REQUIRE(scratch.k_sparse.cols() == n);
  const auto contact_of = [&](Eigen::Index r) -> const gp::Contact& {
    return contacts[scratch.rows[static_cast<std::size_t>(r)].contact];
  };
  const auto point_of = [&](Eigen::Index r) -> const gp::ContactPointState& {
    return contacts.points(contact_of(r))[scratch.rows[static_cast<std::size_t>(r)].point];
  };
  Eigen::Index sharing = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      const gp::Contact& ci = contact_of(i);
      const gp::Contact& cj = contact_of(j);
      bool shares = false;
      for (const gp::BodyId b : {ci.body_a, ci.body_b}) {
        shares = shares || (inertia.inverse_mass[b] > 0.0 && (b == cj.body_a || b == cj.body_b));
      }
      if (!shares) continue;
      ++sharing;
      INFO("entry (" << i << ", " << j << ")");
      CHECK(scratch.k_sparse.coeff(i, j) ==
            Approx(gp::normal_coupling(ci, point_of(i), cj, point_of(j), inertia)).epsilon(1e-14));
    }
  }
  CHECK(n == 10);
  CHECK(scratch.k_sparse.nonZeros() == sharing);
}

TEST_CASE(
    "A wall of 3600 boxes' K, its columns filled in side by side on two threads, holds "
    "normal_coupling's entry wherever two points share a moving body, and nothing else",
    "[FR:Determine-Collision-Response-Over-Time]") {
  // 60 × 60 boxes [1/kg, 1/(kg·m²)], each on the one below (the bottom row on the static body 0)
  // and beside the one to its left, two points a contact: 14,280 points, past the columns from
  // which assemble_sparse shares them out.
  constexpr int kSide = 60;
  const auto box = [](int row, int column) {
    return static_cast<gp::BodyId>(1 + row * kSide + column);
  };
  gp::BodyInertia inertia{{0.0}, {0.0}};
  for (int b = 0; b < kSide * kSide; ++b) {
    inertia.inverse_mass.push_back(1.0 + 0.001 * b);
    inertia.inverse_moment.push_back(6.0 - 0.001 * b);
  }
  gp::ContactSet contacts;
  gp::IslandScratch scratch;
  double arm = 0.1;  // m
  const auto touch = [&](gp::BodyId a, gp::BodyId b, const gp::Vec2& normal) {
    const auto index = static_cast<std::uint32_t>(contacts.size());
    gp::Contact& c = contacts.append(2);
    c.body_a = a;
    c.body_b = b;
    c.normal = normal;
    for (std::uint32_t k = 0; k < 2; ++k) {
      gp::set_arms(contacts.points(c)[k], normal, {arm, -0.5}, {0.3 - arm, 0.5});
      arm = std::fmod(arm + 0.137, 0.5);
      scratch.rows.push_back({index, k});
    }
  };
  // Body by body, each with the contacts it makes with those below and to its left, which puts
  // each body's points in many columns apart.
  std::vector<std::vector<Eigen::Index>> points_on(inertia.inverse_mass.size());
  for (int row = 0; row < kSide; ++row) {
    for (int column = 0; column < kSide; ++column) {
      touch(box(row, column), row == 0 ? 0 : box(row - 1, column), {0.0, 1.0});
      if (column > 0) touch(box(row, column), box(row, column - 1), {1.0, 0.0});
    }
  }
  const auto n = static_cast<Eigen::Index>(scratch.rows.size());
  REQUIRE(n == 14280);
  tbb::task_arena two_threads(2);
  two_threads.execute([&] { gp::assemble_sparse(contacts, inertia, scratch); });
  const auto contact_of = [&](Eigen::Index r) -> const gp::Contact& {
    return contacts[scratch.rows[static_cast<std::size_t>(r)].contact];
  };
  const auto point_of = [&](Eigen::Index r) -> const gp::ContactPointState& {
    return contacts.points(contact_of(r))[scratch.rows[static_cast<std::size_t>(r)].point];
  };
  // The entries expected, counted from the points on each moving body: every two points on a
  // body share it, and two points on both of two bodies (a contact's own) share twice.
  for (Eigen::Index r = 0; r < n; ++r) {
    for (const gp::BodyId b : {contact_of(r).body_a, contact_of(r).body_b}) {
      if (inertia.inverse_mass[b] > 0.0) points_on[b].push_back(r);
    }
  }
  std::vector<std::vector<Eigen::Index>> expected(static_cast<std::size_t>(n));
  for (const auto& on_body : points_on) {
    for (const Eigen::Index i : on_body) {
      for (const Eigen::Index j : on_body) expected[static_cast<std::size_t>(j)].push_back(i);
    }
  }
  Eigen::Index wrong = 0;
  Eigen::Index entries = 0;
  for (Eigen::Index j = 0; j < n; ++j) {
    std::vector<Eigen::Index>& rows = expected[static_cast<std::size_t>(j)];
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    entries += static_cast<Eigen::Index>(rows.size());
    std::size_t k = 0;
    for (gp::SparseK::InnerIterator entry(scratch.k_sparse, j); entry; ++entry, ++k) {
      const double coupling = gp::normal_coupling(contact_of(entry.row()), point_of(entry.row()),
                                                  contact_of(j), point_of(j), inertia);
      // Entries of 1 to 10 1/kg, summed body by body rather than as normal_coupling sums them.
      const bool right =
          k < rows.size() && rows[k] == entry.row() && std::abs(entry.value() - coupling) <= 1e-13;
      wrong += right ? 0 : 1;
    }
    wrong += k == rows.size() ? 0 : 1;
  }
  CHECK(wrong == 0);
  CHECK(scratch.k_sparse.nonZeros() == entries);
}

}  // namespace test_island_matrix
}  // namespace
