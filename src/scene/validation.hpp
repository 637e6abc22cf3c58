#pragma once
// Checks of the input against the SRS data constraints (FR:Verify-Physical_Constraints), made
// when a body or a space is created. Each failure throws InputError naming the field.

#include <string>

#include "scene/body.hpp"
#include "scene/settings.hpp"

namespace gp {

/// Checks `def`, reporting fields as `prefix` + ".mass" and so on (prefix e.g. "bodies[3]"). What
/// the engine derives from the shapes (mass, centre, moment) is checked by the engine, after this.
void validate_body(const BodyDef& def, const std::string& prefix);

/// Checks the settings of a space (finite gravity, G ≥ 0, iteration counts ≥ 0).
void validate_settings(const Settings& settings);

/// Checks a time step: finite and > 0.
void validate_step(double dt, const std::string& field);

/// Checks that `value` is finite, naming `field` when it is not (the Space's setters too).
void validate_finite(double value, const std::string& field);
void validate_finite(const Vec2& value, const std::string& field);

/// A number as the checks' messages show it: 17 significant digits, "nan" for any NaN.
std::string number_text(double value);
/// A vector as "[x, y]", each coordinate as number_text shows it.
std::string number_text(const Vec2& v);

}  // namespace gp
