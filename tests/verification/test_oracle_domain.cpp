// The declared list of scenes outside the oracle's domain in `gamephysics verify`: a listed scene
// is reported with its reason and never run; an unlisted scene that leaves the domain fails its
// row; a scene in the domain gets its error-estimate row.
#include <catch2/catch.hpp>
#include <string>

#include "scene/scene.hpp"
#include "verification/suite/oracle_domain.hpp"
#include "verification/suite/suite.hpp"

namespace {
namespace test_oracle_domain {

gp::Scene shipped(const std::string& name) {
  return gp::load_scene(std::string(GP_SOURCE_DIR) + "/scenes/" + name + ".json");
}

std::vector<double> first_second() {
  return {0.0, 0.5, 1.0};
}

using gp::verification::CheckList;
using gp::verification::oracle_reference;

TEST_CASE("verify: a declared scene is reported with its reason, not run", "[verify][oracle]") {
  CheckList list("test");
  // rain1000 would take the oracle long and then throw: a quick answer shows it was not run.
  const auto r = oracle_reference(list, "rain1000", shipped("rain1000"), first_second(), {});
  CHECK_FALSE(r.has_value());
  REQUIRE(list.rows().size() == 1);
  CHECK(list.rows()[0].passed);
  CHECK(list.rows()[0].criterion == "reported");
  CHECK(list.rows()[0].measured.find("pairs of hulls") != std::string::npos);
}

TEST_CASE("verify: a chaotic pile is compared on what is well posed, not its trajectories",
          "[verify][oracle]") {
  CheckList list("test");
  // settle50 in the event-driven oracle would pass 10,000 events and throw: a quick answer shows
  // it was not run, and says where it is compared.
  const auto r = oracle_reference(list, "settle50", shipped("settle50"), first_second(), {});
  CHECK_FALSE(r.has_value());
  REQUIRE(list.rows().size() == 1);
  CHECK(list.rows()[0].passed);
  CHECK(list.rows()[0].criterion == "reported");
  CHECK(list.rows()[0].measured.find("chaotic pile") != std::string::npos);
  CHECK_FALSE(gp::verification::outside_oracle_domain("settle50").has_value());
}

TEST_CASE("verify: an unlisted scene that leaves the oracle's domain fails", "[verify][oracle]") {
  // The bouncing ball started inside the ground: an overlap the oracle cannot begin from.
  gp::Scene skid = shipped("bouncing_ball");
  for (gp::BodyDef& body : skid.bodies) {
    if (body.type == gp::BodyType::Dynamic) body.position.y() = 0.0;
  }
  CheckList list("test");
  const auto r = oracle_reference(list, "skid", skid, std::vector<double>{0.0, 2.0}, {});
  CHECK_FALSE(r.has_value());
  REQUIRE(list.rows().size() == 1);
  CHECK_FALSE(list.rows()[0].passed);
  CHECK(list.rows()[0].name.find("skid") != std::string::npos);
  CHECK(list.rows()[0].measured.find("overlap") != std::string::npos);
}

TEST_CASE("verify: a scene in the domain comes with the oracle's own error", "[verify][oracle]") {
  CheckList list("test");
  const auto r = oracle_reference(list, "ramp_slide", shipped("ramp_slide"), first_second(), {});
  REQUIRE(r.has_value());
  REQUIRE(list.rows().size() == 1);
  CHECK(list.rows()[0].passed);
  // The re-solve at 100× tighter tolerances moves the 1 s slide by far less than 1e-9 m, and
  // not by nothing (the two runs are distinct solves).
  CHECK(r->estimate.position < 1e-9);
  CHECK(r->estimate.position > 0.0);
}

TEST_CASE("verify: every hard case is compared with the oracle or declared outside its domain",
          "[verify][oracle]") {
  gp::verification::SuiteOptions options;
  options.quick = true;
  const auto rows = gp::verification::hard_case_checks(options);
  int compared = 0;
  int declared = 0;
  for (const auto& row : rows) {
    INFO(row.name << ": " << row.measured << " (" << row.criterion << ")");
    CHECK(row.passed);
    if (row.name.find(": engine against the oracle") != std::string::npos) ++compared;
    if (row.measured.find("declared outside the oracle's domain") != std::string::npos) {
      ++declared;
    }
  }
  // Twelve hard cases in the domain, the touching cradle outside it; the grazing impact has its
  // own comparison with the oracle.
  CHECK(compared == 12);
  CHECK(declared == 1);
}

}  // namespace test_oracle_domain
}  // namespace
