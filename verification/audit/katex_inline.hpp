#pragma once
// KaTeX (installed from the npm registry into tools/web/node_modules by tools/install-web.sh)
// made ready to inline into a page: its script, and its style sheet with the fonts as data URIs,
// so that the page renders equations with no network and no files beside it.

#include <filesystem>
#include <optional>
#include <string>

namespace gp::verification {

struct KatexInline {
  std::string version;  ///< of the katex package
  std::string css;      ///< katex.min.css, each font a data: URI (woff2)
  std::string js;       ///< katex.min.js
};

/// KaTeX from `package` (the katex package's folder: package.json, dist/), or nothing when it is
/// not installed there.
std::optional<KatexInline> load_katex(const std::filesystem::path& package);

/// `bytes` in base64 (RFC 4648), as data: URIs carry them.
std::string base64(const std::string& bytes);

}  // namespace gp::verification
