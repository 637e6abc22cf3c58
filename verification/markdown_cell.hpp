#pragma once
// Text put into the cells of the Markdown tables the verifier writes (the report, the trace).

#include <string>

namespace gp::verification {

/// `text` with each | escaped, so that it stays within one cell of a Markdown table.
inline std::string markdown_cell(const std::string& text) {
  std::string escaped;
  for (char c : text) escaped += c == '|' ? std::string("\\|") : std::string(1, c);
  return escaped;
}

}  // namespace gp::verification
