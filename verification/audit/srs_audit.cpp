#include "verification/audit/srs_audit.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace gp::verification {

SrsAudit run_srs_audit(const std::filesystem::path& root,
                       const std::optional<TestResults>& results) {
  SrsAudit audit{gather_trace_inputs(root), {}, {}};
  audit.inputs.results = results;
  audit.result = analyse(audit.inputs);
  audit.stale =
      stale_traceability(render_traceability(audit.inputs, audit.result), root / "traceability");
  return audit;
}

namespace {

std::string row(const std::string& name, const std::string& value) {
  std::string padded = "  " + name;
  padded.resize(24, ' ');
  return padded + value + "\n";
}

std::string count_kinds(const Catalog& c) {
  std::map<std::string, int> kinds;
  for (const auto& m : c.models) ++kinds[m.kind];
  return std::to_string(kinds["TM"]) + " TM, " + std::to_string(kinds["GD"]) + " GD, " +
         std::to_string(kinds["DD"]) + " DD, " + std::to_string(kinds["IM"]) + " IM";
}

}  // namespace

std::string format_srs_audit(const SrsAudit& audit) {
  const auto& in = audit.inputs;
  const auto& c = in.catalog;
  std::string text = "SRS audit: srs/catalog.json against models/, tests/ and srs/errata.md\n";
  text += row("catalogue",
              std::to_string(c.all_ids().size()) + " items: " + std::to_string(c.goals.size()) +
                  " goals, " + std::to_string(c.assumptions.size()) + " assumptions, " +
                  count_kinds(c) + ", " + std::to_string(c.functional_requirements.size()) +
                  " FR, " + std::to_string(c.nonfunctional_requirements.size()) + " NFR, " +
                  std::to_string(c.likely_changes.size()) + " LC, " +
                  std::to_string(c.unlikely_changes.size()) + " UC; " +
                  std::to_string(c.input_constraints) + " input and " +
                  std::to_string(c.output_constraints) + " output constraints");
  int tested = 0;
  for (const auto& m : c.models) tested += passing_tests_of(in, m.id).empty() ? 0 : 1;
  text += row("functions", std::to_string(in.registrations.size()) + " registered for " +
                               std::to_string(c.models.size()) + " models");
  text += row("tests", std::to_string(in.tests.size()) + " test cases; " + std::to_string(tested) +
                           "/" + std::to_string(c.models.size()) +
                           " models tested by a test that calls the function" +
                           (in.results ? " and passes" : " (results not given)"));
  int written = 0, written_failed = 0, implemented = 0, implemented_failed = 0;
  std::string failed_ids;
  for (const auto& d : in.dimensions) {
    if (d.form == "as written") {
      ++written;
      if (!d.consistent) ++written_failed, failed_ids += (failed_ids.empty() ? "" : " ") + d.id;
    } else {
      ++implemented;
      implemented_failed += d.consistent ? 0 : 1;
    }
  }
  text += row("dimensional checks",
              std::to_string(written - written_failed) + " passed, " +
                  std::to_string(written_failed) + " failed as written (" + failed_ids + "); " +
                  std::to_string(implemented - implemented_failed) + "/" +
                  std::to_string(implemented) + " model functions consistent with units");
  std::map<std::string, int> kinds;
  for (const auto& e : in.errata) ++kinds[e.kind];
  std::string kind_text;
  for (const auto& [kind, n] : kinds) {
    kind_text += (kind_text.empty() ? "" : ", ") + std::to_string(n) + " " + kind;
  }
  text += row("errata", std::to_string(in.errata.size()) + " (" + kind_text + ")");
  int matched = 0, missing = 0, extra = 0, explained = 0;
  for (const auto& e : audit.result.edges) {
    matched += e.status == EdgeStatus::matched;
    missing += e.status == EdgeStatus::srs_only;
    extra += e.status == EdgeStatus::code_only;
    explained += e.status != EdgeStatus::matched && !e.erratum.empty();
  }
  text += row("edges", std::to_string(matched) + " matched, " + std::to_string(missing) +
                           " missing from the code, " + std::to_string(extra) +
                           " extra in the code; " + std::to_string(explained) + "/" +
                           std::to_string(missing + extra) + " differences explained by errata");
  std::string stale;
  for (const auto& s : audit.stale) stale += " " + s;
  text += row("traceability/",
              audit.stale.empty() ? "up to date" : "stale:" + stale + " (run gamephysics trace)");
  text += row("result", audit.passed() ? "PASS" : "FAIL");
  for (const auto& p : audit.result.problems) text += "  problem: " + p + "\n";
  return text;
}

}  // namespace gp::verification
