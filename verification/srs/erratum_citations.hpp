#pragma once
// Where code, tests and docs cite an erratum of srs/errata.md by its id ("E-DD-LINDISP"), so that
// the traceability check can refuse an id that no entry has.

#include <filesystem>
#include <string>
#include <vector>

namespace gp::verification {

struct Citation {
  std::string id;    ///< e.g. "E-DD-LINDISP"
  std::string file;  ///< relative to the repository root
  int line;          ///< 1-based
};

/// The erratum ids in `text`: "E-" then a capital and at least one more capital or digit, in
/// hyphen-separated words, not preceded by a letter, digit, '_' or '-' (so 1E-9 is not one).
std::vector<Citation> citations_in(const std::string& file, const std::string& text);

/// Every citation in README.md and docs/, models/, src/, tests/, verification/, examples/,
/// python/ and srs/errata.md itself, in their source and text files, sorted by file and line.
std::vector<Citation> erratum_citations(const std::filesystem::path& root);

}  // namespace gp::verification
