// The rule of `gamephysics verify` that a criterion sits within 10× of what it measures, or says
// why it must be looser: a row that breaks it is found, and fails the full run.
#include <catch2/catch.hpp>

#include "verification/suite/suite.hpp"

using gp::verification::CheckList;

namespace {
namespace test_criteria_level {

TEST_CASE("verify: a limit more than 10x above its figure needs a reason", "[verify]") {
  CheckList list("test");
  list.within("tight", "", "3e-9 m", "≤ 1e-8 m", {{3e-9, 1e-8}});
  list.within("loose", "", "3e-9 m", "≤ 0.01 m", {{3e-9, 0.01}});
  list.within("loose with a reason", "", "3e-9 m", "≤ 0.01 m", {{3e-9, 0.01}}, "a reason");
  list.within("exact zero", "", "0 m", "≤ 1e-12 m", {{0.0, 1e-12}});
  list.within("one of two loose", "", "1 m, 1e-6 m/s", "≤ 2 m, ≤ 1 m/s", {{1.0, 2.0}, {1e-6, 1.0}});
  list.within("failed", "", "2 m", "≤ 1 m", {{2.0, 1.0}});
  list.within("tight with a reason", "", "3e-9 m", "≤ 1e-8 m", {{3e-9, 1e-8}}, "why");
  const auto& rows = list.rows();
  CHECK(rows[0].passed);
  CHECK(rows[2].criterion.find("looser than 10×: a reason") != std::string::npos);
  CHECK_FALSE(rows[5].passed);
  CHECK(rows[6].criterion == "≤ 1e-8 m (why)");
  const auto loose = gp::verification::loose_rows(rows);
  REQUIRE(loose.size() == 3);
  CHECK(loose[0]->name == "loose");
  CHECK(loose[1]->name == "exact zero");
  CHECK(loose[2]->name == "one of two loose");

  gp::verification::SuiteOptions full;
  const auto judged = gp::verification::criteria_level_checks(rows, full);
  REQUIRE(judged.size() == 1);
  CHECK_FALSE(judged[0].passed);
  CHECK(judged[0].measured.find("test: loose;") != std::string::npos);
  gp::verification::SuiteOptions quick;
  quick.quick = true;
  CHECK(gp::verification::criteria_level_checks(rows, quick)[0].passed);
}

}  // namespace test_criteria_level
}  // namespace
