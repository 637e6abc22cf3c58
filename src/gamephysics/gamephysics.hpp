#pragma once
// GamePhysics: the public API. A Space (FR:Simulation-Space) owns bodies made of shapes; step()
// advances them in time. See examples/two_bodies.cpp.

#include "engine/core.hpp"
#include "engine/force_callback.hpp"
#include "engine/impact.hpp"
#include "engine/numerical_error.hpp"
#include "engine/pipeline.hpp"
#include "engine/space.hpp"
#include "scene/body.hpp"
#include "scene/input_error.hpp"
#include "scene/settings.hpp"
#include "scene/shape.hpp"
