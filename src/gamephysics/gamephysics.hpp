#pragma once
// GamePhysics: the public API. A Space (FR:Simulation-Space) owns bodies made of shapes; step()
// advances them in time. See examples/two_bodies.cpp.

#include "engine/body.hpp"
#include "engine/geometry/shape.hpp"
#include "engine/input_error.hpp"
#include "engine/numerical_error.hpp"
#include "engine/settings.hpp"
#include "engine/space.hpp"
