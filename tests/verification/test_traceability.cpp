// The traceability check on the repository, and proof that it can fail: removing a registration,
// the only test of a model, an erratum, or lying about a call each makes it report a problem.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "verification/traceability/test_calls.hpp"
#include "verification/traceability/trace_report.hpp"

namespace {
namespace test_traceability {

using namespace gp::verification;

const TraceInputs& repository() {
  static const auto inputs = gather_trace_inputs(GP_SOURCE_DIR);
  return inputs;
}
bool reports(const TraceResult& result, const std::string& text) {
  return std::any_of(result.problems.begin(), result.problems.end(),
                     [&](const std::string& p) { return p.find(text) != std::string::npos; });
}

TEST_CASE("Traceability: every model has a function and a test, every difference an erratum",
          "[traceability]") {
  const auto result = analyse(repository());
  for (const auto& problem : result.problems) INFO(problem);
  CHECK(result.problems.empty());
  CHECK(repository().registrations.size() == 24);
}

TEST_CASE("Traceability: the committed traceability/ is up to date", "[traceability]") {
  const auto files = render_traceability(repository(), analyse(repository()));
  const auto stale = stale_traceability(files, GP_SOURCE_DIR "/traceability");
  for (const auto& name : stale) INFO("stale: traceability/" << name << " (run gamephysics trace)");
  CHECK(stale.empty());
  CHECK(files.size() == 14);
}

TEST_CASE("Traceability: rendering is byte-for-byte reproducible", "[traceability]") {
  const auto first = render_traceability(repository(), analyse(repository()));
  const auto again = gather_trace_inputs(GP_SOURCE_DIR);
  CHECK(first == render_traceability(again, analyse(again)));
}

TEST_CASE("Traceability: deleting one registration fails the check", "[traceability]") {
  auto inputs = repository();
  const auto torque = std::find_if(inputs.registrations.begin(), inputs.registrations.end(),
                                   [](const auto& r) { return r.id == "DD:torque"; });
  REQUIRE(torque != inputs.registrations.end());
  inputs.registrations.erase(torque);
  CHECK(reports(analyse(inputs), "DD:torque: no function registers this model"));
}

TEST_CASE("Traceability: deleting the only test of a model fails the check", "[traceability]") {
  auto inputs = repository();
  // Find a model verified by exactly one test case, and delete that test.
  std::string lone;
  for (const auto& model : inputs.catalog.models) {
    if (tests_of(inputs, model.id).size() == 1) lone = model.id;
  }
  REQUIRE_FALSE(lone.empty());
  const auto* only = tests_of(inputs, lone).front();
  inputs.tests.erase(std::find_if(inputs.tests.begin(), inputs.tests.end(),
                                  [&](const TestCase& t) { return t.name == only->name; }));
  CHECK(reports(analyse(inputs), lone + ": no test"));
}

TEST_CASE("Traceability: a test tagged with a model must call its function", "[traceability]") {
  auto inputs = repository();
  const auto add = [&](const std::string& name, const std::string& tag, const std::string& body) {
    inputs.tests.push_back({name, "tests/x.cpp", {tag}, body});
    inputs.test_calls[name] = models_called(body, inputs.registrations);
  };
  add("tag only", "DD:torque", "CHECK(0.5 * 2.0 == 1.0);");
  add("calls it", "DD:torque", "CHECK(gp::dd::torque(Vec2{1, 0}, Vec2{0, 2}) == 2.0);");
  auto result = analyse(inputs);
  CHECK(reports(result, "\"tag only\" is tagged DD:torque but does not call gp::dd::torque"));
  CHECK_FALSE(reports(result, "\"calls it\" is tagged"));
  // Tagged "via:", a test through the engine is listed but neither required to call nor counted.
  add("through the engine", "via:DD:torque", "CHECK(space.step() == 1);");
  CHECK_FALSE(reports(analyse(inputs), "\"through the engine\""));
  // A model whose tagged tests all fail to call its function is not tested.
  for (auto& t : inputs.tests) {
    if (std::erase(t.tags, "DD:kEnergy")) t.tags.push_back("via:DD:kEnergy");
  }
  add("energy by hand", "DD:kEnergy", "CHECK(0.5 * 2.0 == 1.0);");
  CHECK(
      reports(analyse(inputs), "DD:kEnergy: no test tagged with it calls gp::dd::kinetic_energy"));
}

TEST_CASE("Traceability: with results, only a passing test that calls the function counts",
          "[traceability]") {
  auto inputs = repository();
  inputs.results = TestResults{};
  for (const auto& t : inputs.tests) (*inputs.results)[t.name] = true;
  CHECK_FALSE(reports(analyse(inputs), "passed"));
  for (const auto* t : tests_of(inputs, "DD:torque")) (*inputs.results)[t->name] = false;
  CHECK(reports(analyse(inputs), "DD:torque: no test that calls gp::dd::torque passed"));
}

TEST_CASE("Test index: calls through other models count, braces in literals do not",
          "[traceability]") {
  const auto called = models_called("const auto r = gp::im::collision_response(a, b, n, 1.0);",
                                    repository().registrations);
  CHECK(called == std::set<std::string>{"IM:col2D", "DD:chaslesThm", "DD:reVeInColl", "GD:impulse",
                                        "TM:NewtonThirdLawMot", "DD:impulseV", "DD:torque"});
  CHECK(
      models_called("torque(r, F); tm::reaction_force_of(F);", repository().registrations).empty());
  const std::string source =
      "TEST_CASE(\"t\", \"[x]\") { s = \"}\"; c = '}'; // }\n"
      "j = R\"({ \"a\": 1 })\"; /* } */ dd::torque(r, F); }\nafter";
  CHECK_THAT(braced_body(source, 0), Catch::EndsWith("dd::torque(r, F); "));
}

TEST_CASE("Traceability: a registration must declare exactly the models its code calls",
          "[traceability]") {
  auto inputs = repository();
  for (auto& r : inputs.registrations) {
    if (r.id == "IM:transMot") r.uses.push_back("GD:accelGravity");
  }
  CHECK(reports(analyse(inputs), "gp::im::translational_acceleration: registers uses"));
}

TEST_CASE("Traceability: an edge difference without an erratum fails the check", "[traceability]") {
  auto inputs = repository();
  for (auto& e : inputs.errata) e.edges.clear();
  CHECK(
      reports(analyse(inputs), "edge IM:col2D -> DD:torque is used by the code but not declared"));
  CHECK(reports(analyse(inputs), "edge IM:transMot -> GD:accelGravity is declared by the SRS"));
}

TEST_CASE("Traceability: tags, errata and dimensional findings must name real things",
          "[traceability]") {
  auto inputs = repository();
  inputs.tests.push_back({"made up", "tests/x.cpp", {"DD:doesNotExist"}, ""});
  inputs.tests.push_back({"split; name", "tests/x.cpp", {}, ""});
  inputs.errata.push_back(
      {"E-X", "made up", {"DD:doesNotExist"}, "dimension", {}, {"no such test"}});
  const auto result = analyse(inputs);
  CHECK(reports(result, "is tagged DD:doesNotExist, which is not in the SRS"));
  CHECK(reports(result, "\"split; name\" has '[', ']' or ';' in its name"));
  CHECK(reports(result, "E-X: names DD:doesNotExist, not in the SRS"));
  CHECK(reports(result, "E-X: no test is named \"no such test\""));
  auto without_dimension_errata = repository();
  std::erase_if(without_dimension_errata.errata,
                [](const auto& e) { return e.kind == "dimension"; });
  CHECK(reports(analyse(without_dimension_errata),
                "DD:linDisp: fails the dimensional audit but has no erratum of kind dimension"));
}

TEST_CASE("Traceability: an erratum id cited but not in srs/errata.md fails the check",
          "[traceability]") {
  // The bogus id is split in two so that this file itself does not cite it.
  const std::string text =
      "keeps the sign (srs/errata.md, E-"
      "NO-SUCH-ERRATUM).\n"
      "See E-DD-LINDISP; 1E-9 m and E-X are not ids.";
  const auto cited = citations_in("docs/x.md", text);
  REQUIRE(cited.size() == 2);
  CHECK(cited[0].line == 1);
  CHECK(cited[1].id == "E-DD-LINDISP");
  auto inputs = repository();
  CHECK_FALSE(reports(analyse(inputs), "which srs/errata.md does not have"));
  CHECK(inputs.citations.size() > 20);  // the scan reaches code, tests and docs
  inputs.citations.insert(inputs.citations.end(), cited.begin(), cited.end());
  const auto result = analyse(inputs);
  CHECK(reports(result,
                "docs/x.md:1: cites E-"
                "NO-SUCH-ERRATUM, which srs/errata.md does not have"));
  CHECK_FALSE(reports(result, "cites E-DD-LINDISP"));
}

TEST_CASE("Errata: a malformed edge or a field before any erratum is an error", "[traceability]") {
  const auto dir = std::filesystem::temp_directory_path() / "gp_errata_test";
  std::filesystem::create_directories(dir);
  {
    std::ofstream(dir / "bad_edge.md") << "### E-A: title\n- **Edges:** IM:col2D DD:torque\n";
    std::ofstream(dir / "orphan.md") << "- **Kind:** dimension\n";
  }
  CHECK_THROWS_WITH(load_errata(dir / "bad_edge.md"), Catch::Contains("'FROM -> TO'"));
  CHECK_THROWS_WITH(load_errata(dir / "orphan.md"), Catch::Contains("outside an erratum"));
  CHECK_THROWS(load_errata(dir / "missing.md"));
}

TEST_CASE("README names the function and file of every SRS model", "[traceability]") {
  std::ifstream in(GP_SOURCE_DIR "/README.md");
  const std::string readme((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const auto& r : repository().registrations) {
    INFO(r.id);
    CHECK(readme.find("| " + r.id + " | `" + r.function + "` |") != std::string::npos);
  }
}

}  // namespace test_traceability
}  // namespace
