#include <iostream>

#include "cli/commands.hpp"
#include "verification/audit/srs_audit.hpp"

namespace gp::cli {

int verify(const std::filesystem::path& root) {
  const auto audit = verification::run_srs_audit(root);
  std::cout << verification::format_srs_audit(audit);
  return audit.passed() ? 0 : 1;
}

}  // namespace gp::cli
