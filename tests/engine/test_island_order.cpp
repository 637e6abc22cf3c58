// The order in which a large island's points enter its sparse solve (island_contacts_in_order):
// each of the island's contacts once, and a Cholesky factor of K in that order about as sparse as
// with Eigen's AMD taken over the points themselves, where the contacts' own order fills it in.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <utility>
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

TEST_CASE("Two contacts between the same two bodies are each other's neighbour once",
          "[FR:Determine-Collision-Response-Over-Time]") {
  // A body of two shapes touching another twice (contacts 0 and 1, bodies 2 and 1), a third body
  // on it, and the static ground (body 0) under body 1.
  gp::BodyInertia inertia{{0.0, 1.0, 1.0, 1.0}, {0.0, 1.0, 1.0, 1.0}};
  gp::ContactSet contacts;
  for (const auto& [a, b] : {std::pair<gp::BodyId, gp::BodyId>{2, 1}, {2, 1}, {3, 2}, {1, 0}}) {
    gp::Contact& c = contacts.append(1);
    c.body_a = a;
    c.body_b = b;
    c.normal = {0.0, 1.0};
  }
  gp::ContactIslands islands;
  islands.find(contacts, inertia);
  gp::IslandOrderScratch scratch;
  std::vector<std::uint32_t> ordered;
  gp::island_contacts_in_order(contacts, islands, 1, inertia, scratch, ordered);
  std::vector<std::uint32_t> sorted = ordered;
  std::sort(sorted.begin(), sorted.end());
  CHECK(sorted == std::vector<std::uint32_t>{0, 1, 2, 3});
  // The neighbours' lower triangle, by the contacts' places in the island: every entry once, in
  // increasing rows, the diagonal included.
  const Eigen::SparseMatrix<double>& n = scratch.neighbours;
  REQUIRE(n.rows() == 4);
  Eigen::Matrix4d dense = Eigen::Matrix4d::Zero();
  for (Eigen::Index k = 0; k < n.outerSize(); ++k) {
    Eigen::Index last = -1;
    for (Eigen::SparseMatrix<double>::InnerIterator e(n, k); e; ++e) {
      CHECK(e.row() > last);
      last = e.row();
      dense(e.row(), k) += e.value();
    }
  }
  // Places 0 and 1 share bodies 1 and 2, 2 shares body 2 with them, 3 body 1 with them.
  std::vector<std::uint32_t> place(4);
  for (std::uint32_t k = 0; k < 4; ++k) place[islands.order[islands.island_start[1] + k]] = k;
  const auto entry = [&](std::uint32_t c, std::uint32_t d) {
    const std::uint32_t i = std::max(place[c], place[d]);
    const std::uint32_t j = std::min(place[c], place[d]);
    return dense(i, j);
  };
  CHECK(entry(0, 1) == 1.0);
  CHECK(entry(0, 2) == 1.0);
  CHECK(entry(1, 3) == 1.0);
  CHECK(entry(2, 3) == 0.0);
  for (std::uint32_t c = 0; c < 4; ++c) CHECK(entry(c, c) == 1.0);
}

}  // namespace test_island_order
}  // namespace
