#include "engine/geometry/closest_points.hpp"

#include <algorithm>

namespace gp {

SegmentClosestPoints closest_points_between_segments(const Vec2& p1, const Vec2& q1, const Vec2& p2,
                                                     const Vec2& q2) {
  // Minimise |p1 + s d1 − (p2 + t d2)|² over the unit square (Ericson, Real-Time Collision
  // Detection, 5.1.9): the unconstrained s for the infinite lines, clamped, then t for that s,
  // clamped, then s again for a clamped t. Clamping gives exact 0 and 1 at the ends.
  const Vec2 d1 = q1 - p1;
  const Vec2 d2 = q2 - p2;
  const Vec2 r = p1 - p2;
  const double a = d1.squaredNorm();
  const double e = d2.squaredNorm();
  const double f = d2.dot(r);
  const double c = d1.dot(r);
  const double b = d1.dot(d2);
  // a·e·sin²(angle): below this relative size the lines count as parallel, whose unconstrained s
  // would be round-off; any s then gives a closest pair once t is clamped.
  const double denominator = a * e - b * b;
  constexpr double kParallelSineSquared = 1e-12;

  double s = 0.0;
  double t = 0.0;
  if (e == 0.0) {
    s = a > 0.0 ? std::clamp(-c / a, 0.0, 1.0) : 0.0;
  } else {
    if (denominator > kParallelSineSquared * a * e) {
      s = std::clamp((b * f - c * e) / denominator, 0.0, 1.0);
    }
    t = (b * s + f) / e;
    if (t < 0.0) {
      t = 0.0;
      s = a > 0.0 ? std::clamp(-c / a, 0.0, 1.0) : 0.0;
    } else if (t > 1.0) {
      t = 1.0;
      s = a > 0.0 ? std::clamp((b - c) / a, 0.0, 1.0) : 0.0;
    }
  }
  const Vec2 point1 = p1 + s * d1;
  const Vec2 point2 = p2 + t * d2;
  return {point1, point2, s, t, (point1 - point2).squaredNorm()};
}

Vec2 closest_point_on_segment(const Vec2& point, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double length_squared = d.squaredNorm();
  if (length_squared == 0.0) return a;
  return a + std::clamp((point - a).dot(d) / length_squared, 0.0, 1.0) * d;
}

}  // namespace gp
