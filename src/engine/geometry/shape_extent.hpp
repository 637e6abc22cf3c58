#pragma once
// Sizes of a shape that bound how far it moves as its body moves: how far its points reach from
// the centre of mass, and how thick it is (the engine's time-of-impact search: how far its body
// can move before it could miss an impact); and how far its core reaches (the broadphase: how
// far its box can move as its body turns).

#include "scene/shape.hpp"

namespace gp {

/// Farthest any point of `shape` (body frame, centred on the centre of mass) is from the centre
/// of mass [m]: a turn by Δϕ moves no point farther than reach · |Δϕ|.
double reach(const GeometryView& shape);

/// reach() less a disc's or a segment's radius [m]: the farthest point of the shape's core from
/// the centre of mass. A turn by Δϕ moves the shape's bounding box, which its radius surrounds the
/// core by whatever the turn, by no more than core_reach · |Δϕ|.
double core_reach(const GeometryView& shape);

/// Half the least width of `shape` [m]: the radius of a disc or a capsule (0 for a bare
/// segment), the least distance from a polygon's vertex centroid to its edges. A body that has
/// moved less than this into another cannot yet have passed through it.
double half_thickness(const GeometryView& shape);

}  // namespace gp
