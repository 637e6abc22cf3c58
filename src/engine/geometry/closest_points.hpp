#pragma once
// Closest points between points and segments: the distance queries under the narrowphase and the
// signed distance.

#include "gamephysics/models/types.hpp"

namespace gp {

/// Closest points between segment p1–q1 and segment p2–q2 (m). A fraction places its point along
/// its segment (0 at p, 1 at q) and is exactly 0 or 1 when the point is an end; for parallel
/// segments one of the closest pairs is chosen.
struct SegmentClosestPoints {
  Vec2 point1;
  Vec2 point2;
  double fraction1;
  double fraction2;
  double distance_squared;  ///< m²
};

SegmentClosestPoints closest_points_between_segments(const Vec2& p1, const Vec2& q1, const Vec2& p2,
                                                     const Vec2& q2);

/// Point of segment a–b (m) closest to `point` (m).
Vec2 closest_point_on_segment(const Vec2& point, const Vec2& a, const Vec2& b);

}  // namespace gp
