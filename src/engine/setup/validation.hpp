#pragma once
// Checks of the input against the SRS data constraints (FR:Verify-Physical_Constraints), made
// when a body or a space is created. Each failure throws InputError naming the field.

#include <string>

#include "engine/body.hpp"
#include "engine/settings.hpp"

namespace gp {

/// Checks `def`, reporting fields as `prefix` + ".mass" and so on (prefix e.g. "bodies[3]").
void validate_body(const BodyDef& def, const std::string& prefix);

/// Checks that `value` is finite, reporting it as `field`.
void validate_finite(double value, const std::string& field);
void validate_finite(const Vec2& value, const std::string& field);

/// Checks the settings of a space (finite gravity, G ≥ 0, iteration counts ≥ 0).
void validate_settings(const Settings& settings);

/// Checks a time step: finite and > 0.
void validate_step(double dt, const std::string& field);

}  // namespace gp
