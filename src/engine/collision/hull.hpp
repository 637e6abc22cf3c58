#pragma once
// Polygons and segments seen alike: a segment is a two-vertex polygon with a radius, so that one
// separating-axis routine serves polygons, capsules and lines in the narrowphase and the signed
// distance. Internal to collision/.

#include <array>
#include <limits>
#include <span>
#include <variant>

#include "engine/lanes.hpp"
#include "scene/shape.hpp"

namespace gp {

/// A convex outline (counter-clockwise vertices with outward edge normals, m) inflated by
/// `radius` (m). Views the storage it was made from.
struct Hull {
  std::span<const Vec2> vertices;
  std::span<const Vec2> normals;
  double radius;

  int count() const { return static_cast<int>(vertices.size()); }
  int next(int index) const { return index + 1 == count() ? 0 : index + 1; }
};

inline Hull hull_of(const PolygonView& polygon) {
  return {polygon.vertices, polygon.normals, 0.0};
}

/// A box's outline: a Hull whose four vertices are known when compiled, so that the narrowphase's
/// loops over them unroll and its calls inline. Gives the same bits as the Hull of the same box.
struct BoxHull {
  static constexpr double radius = 0.0;
  std::span<const Vec2, 4> vertices;
  std::span<const Vec2, 4> normals;
  static constexpr int count() { return 4; }
  static constexpr int next(int index) { return index == 3 ? 0 : index + 1; }
};

/// Whether `polygon` is a box (four vertices): box_hull_of then views it.
inline bool is_box(const PolygonView& polygon) {
  return polygon.vertices.size() == 4;
}
inline BoxHull box_hull_of(const PolygonView& polygon) {
  return {polygon.vertices.first<4>(), polygon.normals.first<4>()};
}

/// A segment as the two edges a→b and b→a; holds the storage its Hull views.
class SegmentOutline {
 public:
  explicit SegmentOutline(const Segment& segment);
  Hull hull() const { return {vertices_, normals_, radius_}; }

 private:
  std::array<Vec2, 2> vertices_;
  std::array<Vec2, 2> normals_;
  double radius_;
};

/// Calls `visit` with a polygon's or a segment's geometry (not a circle's) seen as a Hull, which
/// lives only for the call.
template <typename Visit>
auto visit_as_hull(const GeometryView& geometry, Visit&& visit) {
  if (const auto* polygon = std::get_if<PolygonView>(&geometry)) return visit(hull_of(*polygon));
  const SegmentOutline outline(*std::get_if<Segment>(&geometry));
  return visit(outline.hull());
}

/// The edge of `reference` along whose normal `other` is farthest out, and that distance (m):
/// max over edges i of min over vertices v of `other` of nᵢ·(v − vᵢ). Radii are not counted.
struct EdgeSeparation {
  int edge;
  double separation;
};

EdgeSeparation max_separation(const Hull& reference, const Hull& other);

/// How `lanes` takes a box's edges, for --explain: "its edges four at a time (AVX2)".
const char* box_lanes_name(Lanes lanes);

/// max_separation of a box against a box, `lanes` edges at a time (kFour only where
/// widest_lanes() is kFour, kTwo only where it is not kOne). Each gives the same edge and
/// separation to the bit; max_separation takes the widest.
EdgeSeparation max_separation_of_boxes(std::span<const Vec2, 4> vertices,
                                       std::span<const Vec2, 4> normals,
                                       std::span<const Vec2, 4> other, Lanes lanes);

/// max_separation of box `a` against box `b` and of `b` against `a`, the widest lanes at a time:
/// the same edges and separations to the bit as max_separation's.
struct BoxSeparations {
  EdgeSeparation a;  ///< a's edge along whose normal b is farthest out
  EdgeSeparation b;  ///< b's edge along whose normal a is farthest out
};
BoxSeparations box_separations(const BoxHull& a, const BoxHull& b);

/// The edge of `hull` (a Hull or a BoxHull) whose normal is most nearly opposite `normal`: the
/// edge that meets the reference edge with that normal.
template <typename Outline>
int incident_edge(const Outline& hull, const Vec2& normal) {
  int best = 0;
  double lowest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < hull.count(); ++i) {
    const double alignment = normal.dot(hull.normals[i]);
    if (alignment < lowest) {
      lowest = alignment;
      best = i;
    }
  }
  return best;
}

}  // namespace gp
