#pragma once
// The check of what the engine derives from a body's shapes (FR:Verify-Physical_Constraints),
// made after the SRS data constraints of the input (validate_body).

#include <string>

#include "scene/body.hpp"

namespace gp {

/// The mass, centre of mass and moment of inertia the engine derives from the shapes, and the
/// shapes placed about that centre, must be finite, and a dynamic body's mass > 0: finite inputs
/// can still overflow them (a disc of radius 1e300 has an infinite area) or underflow the mass to
/// 0 (a disc of radius 1e-200). Throws InputError naming `prefix` + ".shapes" (or one shape).
void validate_derived_mass(const BodyDef& def, const std::string& prefix);

}  // namespace gp
