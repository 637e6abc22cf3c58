#pragma once
// Two sizes of a shape that bound how far its body can move before the oracle could miss an
// impact (the oracle, the engine's time-of-impact search): how far its points reach from the
// centre of mass, and how thick it is.

#include "scene/shape.hpp"

namespace gp {

/// Farthest any point of `shape` (body frame, centred on the centre of mass) is from the centre
/// of mass [m]: a turn by Δϕ moves no point farther than reach · |Δϕ|.
double reach(const GeometryView& shape);

/// Half the least width of `shape` [m]: the radius of a disc or a capsule (0 for a bare
/// segment), the least distance from a polygon's vertex centroid to its edges. A body that has
/// moved less than this into another cannot yet have passed through it.
double half_thickness(const GeometryView& shape);

}  // namespace gp
