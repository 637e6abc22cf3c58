#pragma once
// Moving a shape within its body frame: the engine re-expresses shapes relative to the centre of
// mass, so that a body's position is its centre of mass (as the SRS's p(t) is).

#include "scene/shape.hpp"

namespace gp {

/// `shape` translated by `offset` [m].
Shape translated(const Shape& shape, const Vec2& offset);

}  // namespace gp
