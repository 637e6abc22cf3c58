#pragma once
// The space a scene describes.

#include <memory>

#include "engine/space.hpp"
#include "scene/scene.hpp"

namespace gp {

/// A space with the scene's settings and bodies, added in order so that body i of the file is
/// BodyId i. Throws InputError naming "bodies[i].field" for a body that breaks an SRS data
/// constraint (Space::add_body).
std::unique_ptr<Space> build_space(const Scene& scene);

}  // namespace gp
