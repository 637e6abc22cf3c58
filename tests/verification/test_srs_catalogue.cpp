// The catalogue against the SRS's own counts, and the SRS texts that errata cite, read from the
// catalogue so that a finding is shown to be in the SRS as extracted (srs/extract_catalog.py).
#include <catch2/catch.hpp>
#include <string>

#include "verification/srs/catalog.hpp"

namespace {
const gp::verification::Catalog& catalog() {
  static const auto c = gp::verification::load_catalog(GP_SOURCE_DIR "/srs/catalog.json");
  return c;
}
const nlohmann::json& model(const std::string& id) {
  for (const char* section :
       {"theoretical_models", "general_definitions", "data_definitions", "instance_models"}) {
    for (const auto& m : catalog().json.at(section)) {
      if (m.at("id") == id) return m;
    }
  }
  FAIL("no model " << id);
  throw;
}
std::string text_of(const std::vector<gp::verification::Item>& items, const std::string& id) {
  for (const auto& i : items) {
    if (i.id == id) return i.text;
  }
  return "";
}
}  // namespace

TEST_CASE("Catalogue holds every item of the SRS", "[srs]") {
  const auto& c = catalog();
  CHECK(c.goals.size() == 2);
  CHECK(c.assumptions.size() == 7);
  CHECK(c.models.size() == 24);
  CHECK(c.functional_requirements.size() == 8);
  CHECK(c.nonfunctional_requirements.size() == 5);
  CHECK(c.likely_changes.size() == 4);
  CHECK(c.unlikely_changes.size() == 4);
  CHECK(c.input_constraints == 11);
  CHECK(c.output_constraints == 4);
  CHECK(c.contains("IM:col2D"));
  CHECK(c.contains("LC:Variable-ODE-Solver"));
  CHECK_FALSE(c.contains("DD:nonexistent"));
}

TEST_CASE("A malformed catalogue is reported with its file name", "[srs]") {
  CHECK_THROWS_WITH(gp::verification::load_catalog("/nonexistent/catalog.json"),
                    Catch::Contains("/nonexistent/catalog.json"));
  CHECK_THROWS_WITH(gp::verification::load_catalog(GP_SOURCE_DIR "/srs/errata.md"),
                    Catch::Contains("errata.md"));
}

TEST_CASE("SRS: the derivation of IM:transMot names the angular acceleration α_j",
          "[srs][IM:transMot]") {
  const auto& derivation = model("IM:transMot").at("derivation");
  CHECK(derivation.at(0).get<std::string>().rfind("{α_{j}}=", 0) == 0);
  CHECK(model("IM:transMot").at("equation").get<std::string>().find("α") == std::string::npos);
}

TEST_CASE("SRS: instance models list unused inputs and uncomputed outputs",
          "[srs][IM:transMot][IM:rotMot][IM:col2D]") {
  // IM:transMot takes v_j, IM:rotMot takes ω; neither equation contains them.
  CHECK(model("IM:transMot").at("inputs").at(0) == "{\\boldsymbol{v}\\text{(}t\\text{)}_{j}}");
  CHECK(model("IM:transMot").at("equation").get<std::string>().find("boldsymbol{v}") ==
        std::string::npos);
  CHECK(model("IM:rotMot").at("inputs").at(0) == "ω");
  CHECK(model("IM:rotMot").at("equation").get<std::string>().find("ω") == std::string::npos);
  // IM:col2D's only output is t_c, yet its equation computes v_A(t_c).
  CHECK(model("IM:col2D").at("outputs") == nlohmann::json::array({"{t_{\\text{c}}}"}));
}

TEST_CASE("SRS: instance-model constraints order vectors and forbid negative rotation",
          "[srs][IM:transMot][IM:rotMot][IM:col2D]") {
  const auto has = [](const std::string& id, const char* key, const std::string& constraint) {
    for (const auto& c : model(id).at(key)) {
      if (c == constraint) return true;
    }
    return false;
  };
  CHECK(has("IM:transMot", "input_constraints", "\\boldsymbol{g}\\gt{}0"));
  CHECK(has("IM:col2D", "input_constraints", "\\boldsymbol{n}\\gt{}0"));
  CHECK(has("IM:rotMot", "input_constraints", "ω\\gt{}0"));
  CHECK(has("IM:rotMot", "output_constraints", "{α_{j}}\\gt{}0"));
}

TEST_CASE("SRS: eight data definitions are used by no other item", "[srs]") {
  const auto& c = catalog();
  for (const std::string id : {"DD:chaslesThm", "DD:torque", "DD:kEnergy", "DD:coeffRestitution",
                               "DD:reVeInColl", "DD:impulseV", "DD:potEnergy",
                               "DD:momentOfInertia"}) {
    INFO(id);
    for (const auto& [from, to] : c.items_vs_items) CHECK(to != id);
  }
}

TEST_CASE("SRS: the requirements matrix is empty though the goals name their instance models",
          "[srs]") {
  CHECK(catalog().requirements_vs_items.empty());
  CHECK(catalog().assumptions_vs_assumptions.empty());
}

TEST_CASE("SRS: unlikely changes and A:coordinateSystemTy are traced to nothing", "[srs]") {
  for (const auto& [item, assumption] : catalog().assumptions_vs_items) {
    CHECK(item.rfind("UC:", 0) != 0);
    CHECK(assumption != "A:coordinateSystemTy");
  }
}

TEST_CASE("SRS: FR:Input-Surface-Properties asks for friction that A:dampingInvolvement excludes",
          "[srs]") {
  CHECK_THAT(text_of(catalog().functional_requirements, "FR:Input-Surface-Properties"),
             Catch::Contains("friction"));
  CHECK_THAT(text_of(catalog().assumptions, "A:dampingInvolvement"),
             Catch::Contains("no friction forces"));
}

TEST_CASE("SRS: the NFRs bound learning time from below and name another product",
          "[srs]") {
  const auto& nfr = catalog().nonfunctional_requirements;
  CHECK_THAT(text_of(nfr, "NFR:Usability"), Catch::Contains("no less than 30 to 60 minutes"));
  CHECK_THAT(text_of(nfr, "NFR:Understandability"), Catch::Contains("Tamias2D"));
  CHECK_THAT(text_of(nfr, "NFR:Performance"), Catch::Contains("within 1"));
}

TEST_CASE("SRS: the unit vector d̂ and the normal n are given the unit metre", "[srs]") {
  bool d_hat = false, normal = false;
  for (const auto& s : model("TM:UniversalGravLaw").at("symbols")) {
    if (s.at("symbol") == "\\boldsymbol{\\hat{d}}") d_hat = s.at("unit") == "m";
  }
  for (const auto& s : model("GD:impulse").at("symbols")) {
    if (s.at("symbol") == "\\boldsymbol{n}") normal = s.at("unit") == "m";
  }
  CHECK(d_hat);
  CHECK(normal);
}

TEST_CASE("SRS: the input constraint on length L constrains a symbol no model uses", "[srs]") {
  bool has_length = false;
  for (const auto& row : catalog().json.at("input_constraints")) {
    has_length |= row.at("symbol") == "L";
  }
  CHECK(has_length);
  for (const auto& m : catalog().models) {
    for (const auto& s : model(m.id).at("symbols")) CHECK(s.at("symbol") != "L");
  }
}

TEST_CASE("SRS: names and descriptions with slips", "[srs]") {
  const auto& c = catalog();
  CHECK(c.contains("FR:Verify-Physical_Constraints"));  // '_' among '-'
  CHECK(c.contains("LC:Include-Dampening"));            // dampening, for damping
  bool t_c = false;
  for (const auto& s : model("IM:col2D").at("symbols")) {
    t_c |= s.at("description") == "denotes the time at collision";
  }
  CHECK(t_c);  // rendered by the SRS as "is the denotes the time at collision"
}
