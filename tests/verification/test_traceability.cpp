// The traceability check on the repository, and proof that it can fail: removing a registration,
// the only test of a model, an erratum, or lying about a call each makes it report a problem.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "verification/traceability/trace_report.hpp"

using namespace gp::verification;

namespace {
const TraceInputs& repository() {
  static const auto inputs = gather_trace_inputs(GP_SOURCE_DIR);
  return inputs;
}
bool reports(const TraceResult& result, const std::string& text) {
  return std::any_of(result.problems.begin(), result.problems.end(),
                     [&](const std::string& p) { return p.find(text) != std::string::npos; });
}
}  // namespace

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
  CHECK(reports(analyse(inputs), lone + ": no test is tagged with it"));
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
  inputs.tests.push_back({"made up", "tests/x.cpp", {"DD:doesNotExist"}});
  inputs.tests.push_back({"split; name", "tests/x.cpp", {}});
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
