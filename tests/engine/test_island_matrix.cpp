// The sparse effective-mass matrix of a large island (assemble_sparse), built column by column
// from the points' ends on each body, against the entries the dense one takes, each computed on
// its own from the two points' contacts (normal_coupling).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <vector>

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

}  // namespace test_island_matrix
}  // namespace
