#pragma once
// Scene files as JSON text → a JSON document, with every syntax error reported as InputError
// (FR:Verify-Physical_Constraints).

#include <nlohmann/json.hpp>
#include <string>

namespace gp {

/// Parses the text of a scene file. Throws InputError: a syntax error names "line L, column C"
/// (or "(file)" when nlohmann gives no position, e.g. a number beyond the range of double); a key
/// given twice in one object names its path (e.g. "bodies[2].mass"), because nlohmann::json would
/// otherwise keep the last one silently and a copy-and-paste slip would go unnoticed.
nlohmann::json parse_json_document(const std::string& text);

}  // namespace gp
