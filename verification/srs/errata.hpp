#pragma once
// srs/errata.md, read as data: each finding of the SRS audit with the items it concerns, its kind,
// the traceability edges it explains and the tests that show it.

#include <filesystem>
#include <string>
#include <vector>

#include "verification/srs/catalog.hpp"

namespace gp::verification {

struct Erratum {
  std::string id;                  ///< e.g. "E-DD-LINDISP"
  std::string title;               ///< the heading after the id
  std::vector<std::string> items;  ///< SRS ids concerned
  std::string kind;                ///< dimension, operator, missing-term, constraint, ...
  std::vector<Edge> edges;         ///< edges SRS vs code that this erratum explains
  std::vector<std::string> tests;  ///< names of the test cases that show it
};

/// Reads the entries "### E-...: title" and their "- Items:", "- Kind:", "- Edges:" and
/// "- Shown by:" lines; throws std::runtime_error naming the file and line on a malformed entry.
std::vector<Erratum> load_errata(const std::filesystem::path& file);

}  // namespace gp::verification
