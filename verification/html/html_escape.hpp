#pragma once
// Text put into the HTML pages the verifier writes (the report, the audit page, the viewer).

#include <string>

namespace gp::verification {

/// `text` with &, <, > and " escaped, safe in element content and in quoted attribute values.
std::string html_escape(const std::string& text);

}  // namespace gp::verification
