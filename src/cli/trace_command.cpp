#include <iostream>

#include "cli/commands.hpp"
#include "verification/traceability/trace_report.hpp"

namespace gp::cli {

int trace(const std::filesystem::path& root, const std::filesystem::path& out, bool check_only) {
  const auto inputs = verification::gather_trace_inputs(root);
  const auto result = verification::analyse(inputs);
  const auto files = verification::render_traceability(inputs, result);
  for (const auto& problem : result.problems) std::cerr << "problem: " << problem << "\n";
  if (check_only) {
    const auto stale = verification::stale_traceability(files, out);
    for (const auto& name : stale) std::cerr << "stale: traceability/" << name << "\n";
    return result.problems.empty() && stale.empty() ? 0 : 1;
  }
  verification::write_traceability(files, out);
  std::cout << "wrote " << files.size() << " files to " << out.string() << "\n";
  return result.problems.empty() ? 0 : 1;
}

}  // namespace gp::cli
