#pragma once
// The audit page, audit.html beside the report: every item of the SRS catalogue with its
// equation (rendered by KaTeX, inlined), its C++ function and file, its tests, the verification
// checks that name it and their results, its dimensional checks and its errata; then the SRS's
// four traceability matrices.

#include <filesystem>
#include <optional>
#include <ostream>
#include <vector>

#include "verification/audit/katex_inline.hpp"
#include "verification/audit/srs_audit.hpp"
#include "verification/suite/check.hpp"
#include "verification/traceability/test_results.hpp"

namespace gp::verification {

/// What the page shows beside the audit.
struct AuditEvidence {
  std::vector<Check> checks;  ///< the verification suite's rows; none for the audit alone
  std::optional<TestResults> test_results;  ///< of the Catch2 tests, when a report was given
};

/// Writes the page of `audit` to `out`. Without `katex` the equations are shown as LaTeX source,
/// with a note saying how to install KaTeX.
void write_audit_page(std::ostream& out, const SrsAudit& audit, const AuditEvidence& evidence,
                      const std::optional<KatexInline>& katex);

/// Writes `out_dir`/audit.html with KaTeX from `root`/tools/web/node_modules/katex; returns its
/// path.
std::filesystem::path write_audit_page(const std::filesystem::path& root,
                                       const std::filesystem::path& out_dir, const SrsAudit& audit,
                                       const AuditEvidence& evidence);

}  // namespace gp::verification
