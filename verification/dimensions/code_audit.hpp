#pragma once
// The dimensional audit of the model functions themselves: each one of models/ instantiated with
// Boost.Units quantities of the units its doc comment and the SRS give (gp::verification::UnitVec2
// for vectors). A function whose result has another dimension than its declared one, or that adds
// unlike quantities, does not compile, so the build fails; tests/dimensions/ shows it.

#include <vector>

#include "verification/dimensions/dimensional_audit.hpp"

namespace gp::verification {

/// One check of form "in the code" per model function, with the units of its parameters and of
/// its result; all consistent, since an inconsistent one would not have compiled.
std::vector<DimensionalCheck> code_dimensional_audit();

}  // namespace gp::verification
