// `gamephysics verify`, the main job, and `gamephysics audit`, its SRS audit alone with the audit
// page.
#include <iostream>

#include "cli/commands.hpp"
#include "verification/audit/audit_page.hpp"
#include "verification/audit/srs_audit.hpp"
#include "verification/suite/suite.hpp"

namespace gp::cli {

namespace {

// The SRS audit as the first section of the report: one row per traceability problem, or one
// passing row when there is none.
std::vector<verification::Check> audit_rows(const verification::SrsAudit& audit) {
  verification::CheckList list("SRS audit");
  const auto& in = audit.inputs;
  const std::string figures = std::to_string(in.catalog.all_ids().size()) + " items, " +
                              std::to_string(in.registrations.size()) + " functions, " +
                              std::to_string(in.tests.size()) + " test cases, " +
                              std::to_string(in.errata.size()) + " errata";
  list.check("traceability: every model has a function and a test, every difference an erratum",
             "FR:Verify-Physical_Constraints", figures, "no problem",
             audit.result.problems.empty());
  for (const auto& p : audit.result.problems)
    list.check("traceability", "", p, "no problem", false);
  list.check("traceability/ is up to date", "", audit.stale.empty() ? "up to date" : "stale",
             "matches a fresh render", audit.stale.empty());
  return list.rows();
}

// The Catch2 results in `file`, when given.
std::optional<verification::TestResults> test_results(
    const std::optional<std::filesystem::path>& file) {
  if (!file) return std::nullopt;
  return verification::load_test_results(*file);
}

}  // namespace

int verify(const VerifyOptions& options) {
  const auto results = test_results(options.test_results);
  const auto audit = verification::run_srs_audit(options.root, results);
  std::cout << verification::format_srs_audit(audit) << "\n";
  verification::SuiteOptions suite;
  suite.root = options.root;
  suite.out = options.out;
  suite.quick = options.quick;
  suite.long_runs = options.long_runs;
  suite.speed_repetitions = options.speed_repetitions;
  suite.progress = &std::cout;
  std::cout << "Verification suite against the SUNDIALS oracle ("
            << (options.quick ? "quick" : "full") << "):\n";
  const auto result = verification::run_suite(suite, audit_rows(audit));
  const verification::AuditEvidence evidence{result.checks, results};
  std::cout << "  audit page: "
            << verification::write_audit_page(options.root, options.out, audit, evidence).string()
            << "\n";
  return audit.passed() && result.passed ? 0 : 1;
}

int audit(const std::filesystem::path& root, const std::filesystem::path& out,
          const std::optional<std::filesystem::path>& results) {
  const auto loaded = test_results(results);
  const auto audit = verification::run_srs_audit(root, loaded);
  std::cout << verification::format_srs_audit(audit) << "\n";
  const verification::AuditEvidence evidence{{}, loaded};
  std::cout << "audit page: " << verification::write_audit_page(root, out, audit, evidence).string()
            << "\n";
  return audit.passed() ? 0 : 1;
}

}  // namespace gp::cli
