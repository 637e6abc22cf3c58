#pragma once
// How far apart two placed shapes are, as one continuous number (FR:Determine-Collisions): the
// function a time-of-impact search finds the root of.

#include <limits>

#include "engine/geometry/world_shape.hpp"

namespace gp {

/// Signed distance (m) between `a` and `b`: the gap between them when apart, 0 when touching, and
/// minus the depth of overlap (the length of the shortest translation that separates them) when
/// they overlap. Symmetric in a and b; continuous, and changes no faster than either shape moves
/// (1-Lipschitz in its position). Two segments of radius 0 that cross have distance 0 or the
/// negative of the shorter way out along either's normal. Does not allocate.
///
/// Where two polygons or segments are surely more than `beyond` [m] apart by their separating
/// edges alone, returns that separation instead: a value above `beyond`, found with a fraction of
/// the work, for callers that only ask whether the shapes are that far apart.
double signed_distance(const WorldShapeView& a, const WorldShapeView& b,
                       double beyond = std::numeric_limits<double>::infinity());

}  // namespace gp
