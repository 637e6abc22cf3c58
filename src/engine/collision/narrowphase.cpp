#include "engine/collision/narrowphase.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "engine/collision/hull.hpp"
#include "engine/geometry/closest_points.hpp"

namespace gp {

namespace {

/// Adds the point midway between the surface points `on_a` and `on_b` (m) unless the surfaces
/// are more than `margin` (m) apart.
void add_point(ContactManifold& manifold, const Vec2& on_a, const Vec2& on_b, double depth,
               FeatureId id, double margin) {
  if (-depth > margin) return;
  manifold.points[manifold.count++] = {0.5 * (on_a + on_b), depth, id};
}

}  // namespace

ContactManifold collide_circles(const Circle& a, const Circle& b, const CentreGap& gap,
                                double margin) {
  const double separation = gap.distance - a.radius - b.radius;
  ContactManifold manifold;
  if (separation > margin) return manifold;
  // Concentric circles: every direction is as good; a fixed one keeps runs reproducible.
  manifold.normal = gap.distance > 0.0 ? gap.direction : Vec2(0.0, 1.0);
  add_point(manifold, a.center - a.radius * manifold.normal, b.center + b.radius * manifold.normal,
            -separation, {}, margin);
  return manifold;
}

namespace {

ContactManifold collide_circles(const Circle& a, const Circle& b, double margin) {
  return collide_circles(a, b, centre_gap(a, b), margin);
}

/// Hull as A, circle as B. The circle has one feature, so its one point keeps id {0, 0} as it
/// rolls from face to vertex to face.
ContactManifold collide_hull_circle(const Hull& hull, const Circle& circle, double margin) {
  const double radius = hull.radius + circle.radius;
  const Vec2& center = circle.center;
  int face = 0;
  double separation = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < hull.count(); ++i) {
    const double s = hull.normals[i].dot(center - hull.vertices[i]);
    if (s > separation) {
      separation = s;
      face = i;
    }
  }
  ContactManifold manifold;
  if (separation > radius + margin) return manifold;

  // Nearest point of the hull's core to the centre, and the outward direction there. The face of
  // greatest separation borders the nearest feature, so only its edge and ends are candidates.
  Vec2 outward = hull.normals[face];
  Vec2 nearest = center - separation * outward;
  double distance = separation;
  const bool centre_inside_polygon = hull.count() >= 3 && separation <= 0.0;
  if (!centre_inside_polygon) {
    const Vec2& v1 = hull.vertices[face];
    const Vec2& v2 = hull.vertices[hull.next(face)];
    const bool beyond_v1 = (center - v1).dot(v2 - v1) <= 0.0;
    const bool beyond_v2 = (center - v2).dot(v1 - v2) <= 0.0;
    if (beyond_v1 || beyond_v2) {
      nearest = beyond_v1 ? v1 : v2;
      distance = (center - nearest).norm();
      if (distance - radius > margin) return manifold;
      // A centre exactly on a segment's end has no direction of its own: keep the face's.
      if (distance > 0.0) outward = (center - nearest) / distance;
    }
  }
  manifold.normal = -outward;
  add_point(manifold, nearest + hull.radius * outward, center - circle.radius * outward,
            radius - distance, {}, margin);
  return manifold;
}

/// Clips the incident edge of one hull against the side planes of the reference edge of the
/// other, keeping the clipped ends that are within `margin` of the reference face: 2 points when
/// the edges lie against each other, 1 when only a corner reaches. `Outline`: Hull or BoxHull.
template <typename Outline>
ContactManifold clip(const Outline& reference, int reference_edge, const Outline& incident,
                     int incident_edge, bool reference_is_b, double margin) {
  ContactManifold manifold;
  const Vec2& n = reference.normals[reference_edge];  // out of the reference, towards incident
  const int i11 = reference_edge;
  const int i12 = reference.next(i11);
  const int i21 = incident_edge;
  const int i22 = incident.next(i21);
  const Vec2& v11 = reference.vertices[i11];
  const Vec2& v21 = incident.vertices[i21];
  const Vec2& v22 = incident.vertices[i22];

  // Coordinates along the reference edge from v11. The incident edge runs the other way.
  const Vec2 tangent = cross(1.0, n);
  const double upper1 = (reference.vertices[i12] - v11).dot(tangent);
  const double upper2 = (v21 - v11).dot(tangent);
  const double lower2 = (v22 - v11).dot(tangent);

  manifold.normal = reference_is_b ? n : Vec2(-n);
  const auto add = [&](const Vec2& point, int reference_feature, int incident_feature) {
    const double core_separation = (point - v11).dot(n);
    const Vec2 on_reference = point + (reference.radius - core_separation) * n;
    const Vec2 on_incident = point - incident.radius * n;
    const double depth = reference.radius + incident.radius - core_separation;
    const auto ref_id = static_cast<std::uint8_t>(reference_feature);
    const auto inc_id = static_cast<std::uint8_t>(incident_feature);
    if (reference_is_b) {
      add_point(manifold, on_incident, on_reference, depth, {inc_id, ref_id}, margin);
    } else {
      add_point(manifold, on_reference, on_incident, depth, {ref_id, inc_id}, margin);
    }
  };
  const bool v21_deeper = (v21 - v11).dot(n) < (v22 - v11).dot(n);
  if (upper2 < 0.0 || upper1 < lower2) {
    // The edges meet only end to end (cores touching corner to corner, within round-off): the
    // deeper incident end is the contact.
    if (v21_deeper) {
      add(v21, upper2 < 0.0 ? i11 : i12, i21);
    } else {
      add(v22, upper2 < 0.0 ? i11 : i12, i22);
    }
    return manifold;
  }
  const Vec2 lower = lower2 < 0.0 ? Vec2(v22 + (-lower2 / (upper2 - lower2)) * (v21 - v22)) : v22;
  const Vec2 upper =
      upper2 > upper1 ? Vec2(v22 + ((upper1 - lower2) / (upper2 - lower2)) * (v21 - v22)) : v21;
  if ((upper - lower).dot(tangent) > kContactTolerance) {
    add(lower, i11, i22);
    add(upper, i12, i21);
  } else if ((lower - v11).dot(n) <= (upper - v11).dot(n)) {
    // Clipped ends at the same place along the reference edge (a short overlap, or an incident
    // edge standing straight on it): the shallower adds nothing but an ill-conditioned pair for
    // the solver.
    add(lower, i11, i22);
  } else {
    add(upper, i12, i21);
  }
  return manifold;
}

/// The contact of two outlines (Hull or BoxHull) whose separating axis test found `best_a` (a's
/// edges against b) and `best_b`, neither separating them: clipping, or, when their cores are
/// apart and closest at a vertex of each, one point along the line between those vertices.
template <typename Outline>
ContactManifold contact_of_outlines(const Outline& a, const Outline& b,
                                    const EdgeSeparation& best_a, const EdgeSeparation& best_b,
                                    double margin) {
  const double radius = a.radius + b.radius;
  // The reference face stays on A unless B's separates clearly more, so that it does not flip
  // between near-equal faces from frame to frame and the feature ids stay put.
  const bool reference_is_b = best_b.separation > best_a.separation + kContactTolerance;
  const int edge_a = reference_is_b ? incident_edge(a, b.normals[best_b.edge]) : best_a.edge;
  const int edge_b = reference_is_b ? best_b.edge : incident_edge(b, a.normals[best_a.edge]);

  // Two segments have no axis along their common direction among their edge normals, so the
  // separating axis test alone cannot tell parallel segments apart: measure their gap instead.
  const bool two_segments = a.count() == 2 && b.count() == 2;
  if (two_segments || std::max(best_a.separation, best_b.separation) > kContactTolerance) {
    const int a2 = a.next(edge_a);
    const int b2 = b.next(edge_b);
    const SegmentClosestPoints closest = closest_points_between_segments(
        a.vertices[edge_a], a.vertices[a2], b.vertices[edge_b], b.vertices[b2]);
    const auto at_end = [](double fraction) { return fraction == 0.0 || fraction == 1.0; };
    const double distance = std::sqrt(closest.distance_squared);
    if (at_end(closest.fraction1) && at_end(closest.fraction2) && distance > kContactTolerance) {
      ContactManifold manifold;
      if (distance - radius > margin) return manifold;
      manifold.normal = (closest.point1 - closest.point2) / distance;
      const FeatureId id{static_cast<std::uint8_t>(closest.fraction1 == 0.0 ? edge_a : a2),
                         static_cast<std::uint8_t>(closest.fraction2 == 0.0 ? edge_b : b2)};
      add_point(manifold, closest.point1 - a.radius * manifold.normal,
                closest.point2 + b.radius * manifold.normal, radius - distance, id, margin);
      return manifold;
    }
  }
  return reference_is_b ? clip(b, edge_b, a, edge_a, true, margin)
                        : clip(a, edge_a, b, edge_b, false, margin);
}

/// Separating axis test between two hulls, then their contact (contact_of_outlines).
ContactManifold collide_hulls(const Hull& a, const Hull& b, double margin) {
  const double reach = a.radius + b.radius + margin;
  const EdgeSeparation best_a = max_separation(a, b);
  if (best_a.separation > reach) return {};
  const EdgeSeparation best_b = max_separation(b, a);
  if (best_b.separation > reach) return {};
  return contact_of_outlines(a, b, best_a, best_b, margin);
}

/// The same for two boxes, both ways of the test at once and the contact's loops unrolled: a box
/// pile's narrowphase is mostly this.
ContactManifold collide_boxes(const BoxHull& a, const BoxHull& b, double margin) {
  const BoxSeparations best = box_separations(a, b);
  if (best.a.separation > margin || best.b.separation > margin) return {};
  return contact_of_outlines(a, b, best.a, best.b, margin);
}

/// Two polygons: two boxes by collide_boxes, any others by collide_hulls.
ContactManifold collide_polygons(const PolygonView& a, const PolygonView& b, double margin) {
  if (is_box(a) && is_box(b)) return collide_boxes(box_hull_of(a), box_hull_of(b), margin);
  return collide_hulls(hull_of(a), hull_of(b), margin);
}

bool is_bare_line(const GeometryView& geometry) {
  const auto* segment = std::get_if<Segment>(&geometry);
  return segment != nullptr && segment->radius == 0.0;
}

}  // namespace

ContactManifold collide(const GeometryView& a, const GeometryView& b, double margin) {
  const auto* polygon_a = std::get_if<PolygonView>(&a);
  const auto* polygon_b = std::get_if<PolygonView>(&b);
  if (polygon_a != nullptr && polygon_b != nullptr) {
    return collide_polygons(*polygon_a, *polygon_b, margin);
  }
  const auto* circle_a = std::get_if<Circle>(&a);
  const auto* circle_b = std::get_if<Circle>(&b);
  if (circle_a != nullptr && circle_b != nullptr) {
    return collide_circles(*circle_a, *circle_b, margin);
  }
  if (circle_b != nullptr) {
    return visit_as_hull(
        a, [&](const Hull& hull) { return collide_hull_circle(hull, *circle_b, margin); });
  }
  if (circle_a != nullptr) {
    ContactManifold manifold = visit_as_hull(
        b, [&](const Hull& hull) { return collide_hull_circle(hull, *circle_a, margin); });
    // Only the normal turns: a contact with a circle has id {0, 0} whichever shape is A.
    manifold.normal = -manifold.normal;
    return manifold;
  }
  if (is_bare_line(a) && is_bare_line(b)) return {};
  return visit_as_hull(a, [&](const Hull& hull_a) {
    return visit_as_hull(b,
                         [&](const Hull& hull_b) { return collide_hulls(hull_a, hull_b, margin); });
  });
}

ContactManifold collide(const PackedGeometry& a, const PackedGeometry& b, double margin) {
  // The two pairs of a pile, boxes and discs, straight to their collision without a view.
  if (a.kind() == ShapeKind::kPolygon && b.kind() == ShapeKind::kPolygon) {
    return collide_polygons(a.polygon(), b.polygon(), margin);
  }
  if (two_discs(a, b)) return collide_circles(a.circle(), b.circle(), margin);
  return collide(a.view(), b.view(), margin);
}

}  // namespace gp
