#pragma once
// A time-dependent force on a body, given by the user's program.

#include <functional>

#include "engine/core.hpp"

namespace gp {

/// F_j(t), τ_j(t) of one body, given the time [s] and the body's state at that time.
using ForceCallback = std::function<Wrench(double t, BodyId body, const BodyState& state)>;

}  // namespace gp
