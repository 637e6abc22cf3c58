#pragma once
// The SRS audit that `gamephysics verify` prints: catalogue, functions, tests, dimensional checks,
// errata and edges, with every failed check listed.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "verification/traceability/trace_report.hpp"

namespace gp::verification {

struct SrsAudit {
  TraceInputs inputs;
  TraceResult result;
  std::vector<std::string> stale;  ///< files of traceability/ that differ from a fresh render

  bool passed() const { return result.problems.empty() && stale.empty(); }
};

/// Runs the traceability checks on the tree at `root` and compares traceability/ with a fresh
/// render. With the unit tests' `results`, a model counts as tested only by a test that passed.
SrsAudit run_srs_audit(const std::filesystem::path& root,
                       const std::optional<TestResults>& results = std::nullopt);

/// The summary table, then one line per problem.
std::string format_srs_audit(const SrsAudit& audit);

}  // namespace gp::verification
