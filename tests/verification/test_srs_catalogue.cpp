// The catalogue against the SRS's own counts, and the SRS texts that errata cite, read from the
// catalogue so that a finding is shown to be in the SRS as extracted (srs/extract_catalog.py).
#include <catch2/catch.hpp>
#include <string>

#include "verification/srs/catalog.hpp"

namespace {
namespace test_srs_catalogue {
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
  for (const std::string id :
       {"DD:chaslesThm", "DD:torque", "DD:kEnergy", "DD:coeffRestitution", "DD:reVeInColl",
        "DD:impulseV", "DD:potEnergy", "DD:momentOfInertia"}) {
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

TEST_CASE("SRS: the NFRs bound learning time from below and name another product", "[srs]") {
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

std::string description_of(const std::string& id, const std::string& symbol) {
  for (const auto& s : model(id).at("symbols")) {
    if (s.at("symbol") == symbol) return s.at("description");
  }
  return "";
}
bool traced(const std::vector<gp::verification::Edge>& edges, const std::string& from,
            const std::string& to) {
  for (const auto& edge : edges) {
    if (edge == gp::verification::Edge{from, to}) return true;
  }
  return false;
}

TEST_CASE("SRS: j is the impulse and the index of a body", "[srs]") {
  CHECK(description_of("GD:impulse", "j") == "impulse (scalar)");
  CHECK(description_of("IM:col2D", "j") == "impulse (scalar)");
  CHECK(description_of("IM:transMot", "{\\boldsymbol{F}_{j}}") ==
        "force applied to the j-th body at time t");
}

TEST_CASE("SRS: A and B are points in one model and bodies in the next", "[srs]") {
  CHECK(description_of("DD:chaslesThm", "{\\boldsymbol{v}\\text{(}t\\text{)}_{\\text{B}}}") ==
        "velocity at point B");
  CHECK(description_of("IM:col2D", "{\\boldsymbol{v}\\text{(}t\\text{)}_{\\text{A}}}") ==
        "velocity at point A");
  CHECK(description_of("GD:impulse", "{m_{\\text{A}}}") == "mass of rigid body A");
}

TEST_CASE("SRS: d is a scalar distance and a vector named a distance, of no stated direction",
          "[srs]") {
  CHECK(description_of("DD:momentOfInertia", "{d_{j}}") ==
        "distance between the j-th particle and the axis of rotation");
  CHECK(description_of("TM:UniversalGravLaw", "\\boldsymbol{d}") ==
        "distance between the center of mass of the rigid bodies");
}

TEST_CASE("SRS: the collision normal and the contact arms have no direction or definition",
          "[srs]") {
  CHECK(description_of("GD:impulse", "\\boldsymbol{n}") == "collision normal vector");
  // u_AP and u_BP appear only inside ‖u_AP * n‖ and ‖u_BP * n‖.
  CHECK(description_of("GD:impulse", "{\\boldsymbol{u}_{\\text{A}\\text{P}}}").empty());
  CHECK_FALSE(description_of("GD:impulse",
                             "|{\\boldsymbol{u}_{\\text{A}\\text{P}}}\\text{*}\\boldsymbol{n}|")
                  .empty());
}

TEST_CASE("SRS: no assumption states the direction of positive rotation or instant collisions",
          "[srs]") {
  CHECK_THAT(text_of(catalog().assumptions, "A:axesDefined"),
             Catch::Equals("The axes are defined using right-handed coordinate system."));
  for (const auto& a : catalog().assumptions) {
    INFO(a.id);
    CHECK_THAT(a.text, !Catch::Contains("clockwise") && !Catch::Contains("instant") &&
                           !Catch::Contains("impuls") && !Catch::Contains("uniform"));
  }
}

TEST_CASE("SRS: the assumption matrix leaves out assumptions the models use", "[srs]") {
  const auto& marks = catalog().assumptions_vs_items;
  CHECK(traced(marks, "GD:impulse", "A:collisionType"));  // the reading works
  CHECK_FALSE(traced(marks, "GD:impulse", "A:dampingInvolvement"));
  CHECK_FALSE(traced(marks, "DD:chaslesThm", "A:axesDefined"));
  CHECK_FALSE(traced(marks, "DD:chaslesThm", "A:objectDimension"));
  for (const auto& [item, assumption] : marks) CHECK(item != "DD:torque");
}

TEST_CASE("SRS: derivations that use Newton's second law are not traced to it", "[srs]") {
  const auto& uses = catalog().items_vs_items;
  // GD:accelGravity equates the force with m g; DD:impulseV starts from F = m a.
  CHECK_THAT(model("GD:accelGravity").at("derivation").at(2).get<std::string>(),
             Catch::EndsWith("=m\\,\\boldsymbol{g}"));
  CHECK_THAT(model("DD:impulseV").at("derivation").at(0).get<std::string>(),
             Catch::StartsWith("\\boldsymbol{F}=m\\,\\boldsymbol{a}"));
  CHECK(traced(uses, "GD:accelGravity", "TM:UniversalGravLaw"));  // the reading works
  CHECK_FALSE(traced(uses, "GD:accelGravity", "TM:NewtonSecLawMot"));
  CHECK_FALSE(traced(uses, "DD:impulseV", "TM:NewtonSecLawMot"));
}

TEST_CASE("SRS: the derivations of the instance models reach F/m and τ/I by a derivative",
          "[srs][IM:transMot][IM:rotMot]") {
  // Two steps each: a derivative, then the equation; no step states F = m a or τ = I α.
  for (const std::string id : {"IM:transMot", "IM:rotMot"}) {
    INFO(id);
    const auto& steps = model(id).at("derivation");
    REQUIRE(steps.size() == 2);
    CHECK_THAT(steps.at(0).get<std::string>(), Catch::Contains("\\,dt}"));
    CHECK(steps.at(1) == model(id).at("equation"));
  }
  CHECK_FALSE(model("GD:impulse").contains("derivation"));
}

TEST_CASE("SRS: notes and descriptions that name the wrong quantity", "[srs]") {
  CHECK_THAT(model("IM:col2D").at("notes").at(0).get<std::string>(),
             Catch::Contains("initial conditions for position, velocity, orientation, and "
                             "angular acceleration"));
  CHECK_THAT(text_of(catalog().goals, "GS:Determine-Angular-Properties"),
             Catch::Contains("angular velocities"));
  CHECK(description_of("IM:transMot", "{m_{j}}") == "mass of the j-th particle");
  CHECK_THAT(model("DD:chaslesThm").at("notes").at(0).get<std::string>(),
             Catch::Contains("at the origin (axis of rotation)"));
}

}  // namespace test_srs_catalogue
}  // namespace
