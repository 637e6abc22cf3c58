// The dimensional audit against a hand analysis of the SRS's equations with the units of its
// table of symbols (srs/errata.md lists the reasoning for each failure).
#include <catch2/catch.hpp>
#include <set>

#include "verification/dimensions/dimensional_audit.hpp"

TEST_CASE("Dimensional audit finds exactly the SRS's dimensional errors", "[dimensions]") {
  std::set<std::string> failing, written, implemented_failing;
  for (const auto& check : gp::verification::dimensional_audit()) {
    if (check.form == "as written") {
      written.insert(check.id);
      if (!check.consistent) failing.insert(check.id);
    } else if (!check.consistent) {
      implemented_failing.insert(check.id);
    }
  }
  CHECK(written.size() == 24);  // every TM, GD, DD and IM
  // By hand: u = dp/dt and θ = dϕ/dt equate a quantity with its rate; d̂ and n carry metres.
  CHECK(failing == std::set<std::string>{"DD:angDisp", "DD:linDisp", "GD:accelGravity",
                                         "GD:impulse", "IM:col2D", "TM:UniversalGravLaw"});
  CHECK(implemented_failing.empty());
}

TEST_CASE("Dimensional audit reports the dimensions on each side", "[dimensions]") {
  for (const auto& check : gp::verification::dimensional_audit()) {
    if (check.id == "DD:linDisp" && check.form == "as written") {
      CHECK(check.lhs_dimension == "m");
      CHECK(check.rhs_dimension == "m s^-1");
    }
    if (check.id == "GD:impulse" && check.form == "as written") {
      CHECK_THAT(check.rhs_dimension, Catch::StartsWith("inconsistent sum"));
    }
  }
}
