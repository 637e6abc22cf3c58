// The order in which a large island's points enter its sparse solve (island_contacts_in_order):
// each of the island's contacts once, and a Cholesky factor of K in that order about as sparse as
// with Eigen's AMD taken over the points themselves, where the contacts' own order fills it in.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>

#include "engine/solver/contact_islands.hpp"
#include "engine/solver/island_order.hpp"
#include "engine/solver/island_solver.hpp"

namespace {
namespace test_island_order {

// A pyramid's contacts as a pile's narrowphase finds them, row by row: each box of rows 1 and up
// on the two below it (two points each), each beside the next in its row (two points), and the
// bottom row on the static ground, body 0. Arms differ from point to point.
struct Pyramid {
  gp::BodyInertia inertia;
  gp::ContactSet contacts;
};

Pyramid pyramid(int rows) {
  Pyramid p;
  p.inertia.inverse_mass.push_back(0.0);
  p.inertia.inverse_moment.push_back(0.0);
  std::vector<std::vector<gp::BodyId>> box(static_cast<std::size_t>(rows));
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < rows - i; ++j) {
      box[static_cast<std::size_t>(i)].push_back(
          static_cast<gp::BodyId>(p.inertia.inverse_mass.size()));
      p.inertia.inverse_mass.push_back(1.0);
      p.inertia.inverse_moment.push_back(6.0);
    }
  }
  double arm = 0.1;
  const auto touch = [&](gp::BodyId a, gp::BodyId b, const gp::Vec2& normal) {
    gp::Contact& c = p.contacts.append(2);
    c.body_a = a;
    c.body_b = b;
    c.normal = normal;
    for (gp::ContactPointState& point : p.contacts.points(c)) {
      gp::set_arms(point, normal, {arm, -0.5}, {0.3 - arm, 0.5});
      arm = std::fmod(arm + 0.137, 0.5);
    }
  };
  for (int i = 0; i < rows; ++i) {
    const auto& row = box[static_cast<std::size_t>(i)];
    for (std::size_t j = 0; j < row.size(); ++j) {
      if (i == 0) {
        touch(row[j], 0, {0.0, 1.0});
      } else {
        const auto& below = box[static_cast<std::size_t>(i - 1)];
        touch(row[j], below[j], {0.0, 1.0});
        touch(row[j], below[j + 1], {0.0, 1.0});
      }
      if (j + 1 < row.size()) touch(row[j + 1], row[j], {1.0, 0.0});
    }
  }
  return p;
}

// The entries of the Cholesky factor of K (with 1 added to its diagonal, so that it is definite)
// of the points of `contacts` in the order given, each contact's points together.
Eigen::Index factor_entries(const Pyramid& p, const std::vector<std::uint32_t>& contacts) {
  gp::IslandScratch scratch;
  for (const std::uint32_t c : contacts) {
    for (std::uint32_t k = 0; k < static_cast<std::uint32_t>(p.contacts[c].count()); ++k) {
      scratch.rows.push_back({c, k});
    }
  }
  gp::assemble_sparse(p.contacts, p.inertia, scratch);
  gp::SparseK k = scratch.k_sparse;
  for (Eigen::Index i = 0; i < k.rows(); ++i) k.coeffRef(i, i) += 1.0;
  Eigen::SimplicialLLT<gp::SparseK, Eigen::Lower, Eigen::NaturalOrdering<int>> factor(k);
  REQUIRE(factor.info() == Eigen::Success);
  return factor.matrixL().nestedExpression().nonZeros();
}

TEST_CASE(
    "A large island's contacts are ordered so that K's factor stays as sparse as AMD over its "
    "points keeps it",
    "[FR:Determine-Collision-Response-Over-Time]") {
  const Pyramid p = pyramid(30);
  gp::ContactIslands islands;
  islands.find(p.contacts, p.inertia);
  const std::size_t root = 1;  // the lowest movable body: the whole pyramid is one island
  REQUIRE(islands.island_end[root] - islands.island_start[root] == p.contacts.size());

  gp::IslandOrderScratch scratch;
  std::vector<std::uint32_t> ordered;
  gp::island_contacts_in_order(p.contacts, islands, root, p.inertia, scratch, ordered);
  std::vector<std::uint32_t> own(islands.order.begin() + islands.island_start[root],
                                 islands.order.begin() + islands.island_end[root]);
  std::vector<std::uint32_t> sorted = ordered;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::uint32_t> expected = own;
  std::sort(expected.begin(), expected.end());
  CHECK(sorted == expected);

  // The reference: Eigen's AMD over the points' own graph, K's pattern in the contacts' order.
  gp::IslandScratch in_own_order;
  for (const std::uint32_t c : own) {
    for (std::uint32_t k = 0; k < 2; ++k) in_own_order.rows.push_back({c, k});
  }
  gp::assemble_sparse(p.contacts, p.inertia, in_own_order);
  gp::SparseK k = in_own_order.k_sparse;
  for (Eigen::Index i = 0; i < k.rows(); ++i) k.coeffRef(i, i) += 1.0;
  Eigen::SimplicialLLT<gp::SparseK, Eigen::Lower, Eigen::AMDOrdering<int>> by_points(k);
  REQUIRE(by_points.info() == Eigen::Success);
  const Eigen::Index amd_points = by_points.matrixL().nestedExpression().nonZeros();

  const Eigen::Index ours = factor_entries(p, ordered);
  const Eigen::Index unordered = factor_entries(p, own);
  INFO("factor entries: contacts ordered " << ours << ", AMD over the points " << amd_points
                                           << ", the contacts' own order " << unordered);
  CHECK(ours <= 1.1 * static_cast<double>(amd_points));
  // 115,377 entries against 217,677 for 30 rows: the contacts' own order goes row by row, whose
  // band widens with the base.
  CHECK(unordered > 1.5 * static_cast<double>(ours));
}

}  // namespace test_island_order
}  // namespace
