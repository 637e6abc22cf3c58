#pragma once
// One body of a scene file, with its shapes and their surface properties, as a BodyDef
// (FR:Input-Initial-Conditions, FR:Input-Surface-Properties). The format's rules are checked
// here; the SRS data constraints (m > 0, I > 0, 0 ≤ C_R ≤ 1, 0 ≤ ϕ ≤ 2π) are checked by
// Space::add_body, which names the fields alike.

#include <nlohmann/json.hpp>
#include <string>

#include "scene/body.hpp"

namespace gp {

/// The body described by `value`, whose JSON path is `path` (e.g. "bodies[3]"). Throws
/// InputError naming the field for unknown or missing fields, wrong types, an unknown body or
/// shape type, a field that has no effect on the body's type, and a degenerate shape.
BodyDef read_body(const nlohmann::json& value, const std::string& path);

}  // namespace gp
