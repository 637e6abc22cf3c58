#include "verification/oracle/geometry/contact_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "verification/oracle/geometry/placement.hpp"

namespace gp::oracle {

namespace {

using Kind = Feature::Kind;

/// m: how much deeper than the distance a clipped point may be found by round-off alone; a
/// nanometre, far below any contact margin and far above the round-off of shapes under a
/// kilometre.
constexpr double kRoundOff = 1e-9;

/// The feature pair that sets the distance between the cores, and that distance [m] (negative:
/// the penetration depth).
struct CoreContact {
  double distance;
  Feature feature;
};

int count(const PlacedHull& hull) {
  return static_cast<int>(hull.vertices.size());
}

const Vec2& edge_end(const PlacedHull& hull, int edge) {
  return hull.vertices[(edge + 1) % count(hull)];
}

/// Whether `point` lies in the core of `hull`: inside or on a polygon, on a segment, or on a
/// disc's centre.
bool in_core(const Vec2& point, const PlacedHull& hull) {
  const int n = count(hull);
  if (n == 1) return point == hull.vertices[0];
  if (n == 2) {
    const Vec2& s = hull.vertices[0];
    const Vec2 along = hull.vertices[1] - s;
    const double t = (point - s).dot(along);
    return cross(along, point - s) == 0.0 && t >= 0.0 && t <= along.squaredNorm();
  }
  for (int i = 0; i < n; ++i) {
    if ((point - hull.vertices[i]).dot(edge_normal(hull.vertices, i)) > 0.0) return false;
  }
  return true;
}

/// Whether segments p0–p1 and q0–q1 cross at a point inside both.
bool edges_cross(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
  const double p_q0 = cross(p1 - p0, q0 - p0);
  const double p_q1 = cross(p1 - p0, q1 - p0);
  const double q_p0 = cross(q1 - q0, p0 - q0);
  const double q_p1 = cross(q1 - q0, p1 - q0);
  return p_q0 * p_q1 < 0.0 && q_p0 * q_p1 < 0.0;
}

bool cores_overlap(const PlacedHull& a, const PlacedHull& b) {
  for (const Vec2& v : a.vertices) {
    if (in_core(v, b)) return true;
  }
  for (const Vec2& v : b.vertices) {
    if (in_core(v, a)) return true;
  }
  for (int i = 0; i < edge_count(count(a)); ++i) {
    for (int j = 0; j < edge_count(count(b)); ++j) {
      if (edges_cross(a.vertices[i], edge_end(a, i), b.vertices[j], edge_end(b, j))) return true;
    }
  }
  return false;
}

/// Whether the foot of `point` on the line of edge `edge` of `hull` lies strictly inside the edge.
bool projects_inside(const Vec2& point, const PlacedHull& hull, int edge) {
  const Vec2& start = hull.vertices[edge];
  const Vec2 along = edge_end(hull, edge) - start;
  const double t = (point - start).dot(along);
  return t > 0.0 && t < along.squaredNorm();
}

/// The mean of a hull's vertices: inside it, or on it for a disc or a segment.
Vec2 middle(const PlacedHull& hull) {
  Vec2 sum = Vec2::Zero();
  for (const Vec2& v : hull.vertices) sum += v;
  return sum / static_cast<double>(count(hull));
}

/// Whether `point`, a vertex of `other`, faces edge `edge` of `hull` (cores apart): it lies on the
/// outer side of a polygon's edge; for a segment, `other` lies on that side. Apart from the
/// segment and closest to its inside, `other` lies wholly on one side of its line, and its middle
/// decides that side even when `point` is on the line within round-off.
bool faces(const Vec2& point, const PlacedHull& other, const PlacedHull& hull, int edge) {
  const auto gap = [&](const Vec2& p, int e) {
    return (p - hull.vertices[e]).dot(edge_normal(hull.vertices, e));
  };
  if (count(hull) == 2) {
    const double side = gap(middle(other), 0) != 0.0 ? gap(middle(other), 0) : gap(point, 0);
    return (side >= 0.0) == (edge == 0);
  }
  return gap(point, edge) >= 0.0;
}

/// Apart cores: the closest pair is a vertex of one against a vertex or an edge of the other.
/// Edge features win ties, so that a vertex facing an edge keeps the edge's normal.
CoreContact closest_features(const PlacedHull& a, const PlacedHull& b) {
  CoreContact best{std::numeric_limits<double>::infinity(), {Kind::VertexVertex, 0, 0}};
  // A vertex's distance to an edge it projects into; only the closest pair's side is sure.
  const auto consider = [&](const Feature& f, bool edge) {
    const double gap = std::abs(feature_gap(f, a, b));
    if (gap < best.distance || (edge && gap == best.distance)) best = {gap, f};
  };
  for (int i = 0; i < count(a); ++i) {
    for (int j = 0; j < count(b); ++j) consider({Kind::VertexVertex, i, j}, false);
  }
  for (int i = 0; i < count(a); ++i) {
    for (int j = 0; j < edge_count(count(b)); ++j) {
      if (projects_inside(a.vertices[i], b, j) && faces(a.vertices[i], a, b, j)) {
        consider({Kind::VertexEdge, i, j}, true);
      }
    }
  }
  for (int j = 0; j < count(b); ++j) {
    for (int i = 0; i < edge_count(count(a)); ++i) {
      if (projects_inside(b.vertices[j], a, i) && faces(b.vertices[j], b, a, i)) {
        consider({Kind::EdgeVertex, i, j}, true);
      }
    }
  }
  return best;
}

/// The separation [m] along the normal of edge `edge` of `owner` of the other hull `other`: the
/// gap of other's deepest vertex, whose index goes to `deepest`.
double axis_separation(const PlacedHull& owner, int edge, const PlacedHull& other, int& deepest) {
  const Vec2 normal = edge_normal(owner.vertices, edge);
  double separation = std::numeric_limits<double>::infinity();
  for (int k = 0; k < count(other); ++k) {
    const double gap = (other.vertices[k] - owner.vertices[edge]).dot(normal);
    if (gap < separation) {
      separation = gap;
      deepest = k;
    }
  }
  return separation;
}

/// Overlapping cores: the separating axis of least penetration among the edge normals of both,
/// with the other hull's vertex deepest along it. Two coincident points have no axis: 0.
CoreContact least_penetration(const PlacedHull& a, const PlacedHull& b) {
  CoreContact best{-std::numeric_limits<double>::infinity(), {Kind::VertexVertex, 0, 0}};
  for (int i = 0; i < edge_count(count(a)); ++i) {
    int j = 0;
    const double separation = axis_separation(a, i, b, j);
    if (separation > best.distance) best = {separation, {Kind::EdgeVertex, i, j}};
  }
  for (int j = 0; j < edge_count(count(b)); ++j) {
    int i = 0;
    const double separation = axis_separation(b, j, a, i);
    if (separation > best.distance) best = {separation, {Kind::VertexEdge, i, j}};
  }
  if (best.feature.kind == Kind::VertexVertex) best.distance = 0.0;
  return best;
}

/// `a` and `b` are the cores (radius 0).
CoreContact core_contact(const PlacedHull& a, const PlacedHull& b) {
  return cores_overlap(a, b) ? least_penetration(a, b) : closest_features(a, b);
}

/// The feature pairs of the contact whose deepest (or closest) pair is `main`: that one alone for
/// a vertex against a vertex or a disc against an edge; else the incident edge clipped to the
/// reference edge's side planes.
std::vector<Feature> clipped_features(const Feature& main, const PlacedHull& a,
                                      const PlacedHull& b) {
  if (main.kind == Kind::VertexVertex) return {main};
  const bool reference_is_b = main.kind == Kind::VertexEdge;
  const PlacedHull& reference = reference_is_b ? b : a;
  const PlacedHull& incident = reference_is_b ? a : b;
  const int edge = reference_is_b ? main.b : main.a;
  if (count(incident) == 1) return {main};

  const Vec2 normal = edge_normal(reference.vertices, edge);
  int incident_edge = 0;
  for (int k = 1; k < edge_count(count(incident)); ++k) {
    if (edge_normal(incident.vertices, k).dot(normal) <
        edge_normal(incident.vertices, incident_edge).dot(normal)) {
      incident_edge = k;
    }
  }
  const int ends[2] = {incident_edge, (incident_edge + 1) % count(incident)};
  const int reference_ends[2] = {edge, (edge + 1) % count(reference)};
  // Coordinates along the reference edge, from its start (0) to its end (`length`), in m·|edge|.
  const Vec2& start = reference.vertices[edge];
  const Vec2 along = edge_end(reference, edge) - start;
  const double length = along.squaredNorm();
  const double t[2] = {(incident.vertices[ends[0]] - start).dot(along),
                       (incident.vertices[ends[1]] - start).dot(along)};

  const auto vertex_on_reference = [&](int vertex) {
    return reference_is_b ? Feature{Kind::VertexEdge, vertex, edge}
                          : Feature{Kind::EdgeVertex, edge, vertex};
  };
  // A reference end against the incident edge, when its foot on that edge's line lies on the
  // edge, or when the end is inside the incident core (a deep overlap), where the line measures
  // its depth. Outside the core with its foot off the edge, the gap would measure to a line the
  // hull does not reach there.
  const auto reference_vertex_on_incident = [&](int vertex, std::vector<Feature>& features) {
    const Vec2& point = reference.vertices[vertex];
    if (!projects_inside(point, incident, incident_edge) && !in_core(point, incident)) return;
    features.push_back(reference_is_b ? Feature{Kind::EdgeVertex, incident_edge, vertex}
                                      : Feature{Kind::VertexEdge, vertex, incident_edge});
  };
  std::vector<Feature> features;
  for (int e = 0; e < 2; ++e) {
    if (t[e] >= 0.0 && t[e] <= length) features.push_back(vertex_on_reference(ends[e]));
  }
  const double low = std::min(t[0], t[1]);
  const double high = std::max(t[0], t[1]);
  if (low < 0.0 && 0.0 < high) reference_vertex_on_incident(reference_ends[0], features);
  if (low < length && length < high) reference_vertex_on_incident(reference_ends[1], features);
  if (features.empty()) features.push_back(main);  // the edges meet end to end
  return features;
}

PlacedHull core_of(const PlacedHull& hull) {
  return {hull.vertices, 0.0};
}

bool bare_line(const Hull& hull) {
  return hull.vertices.size() == 2 && hull.radius == 0.0;
}

}  // namespace

double signed_distance(const Hull& a, const Pose& pa, const Hull& b, const Pose& pb) {
  const std::vector<Vec2> va = placed_vertices(a, pa);
  const std::vector<Vec2> vb = placed_vertices(b, pb);
  return core_contact({va, 0.0}, {vb, 0.0}).distance - a.radius - b.radius;
}

ContactGeometry contact_geometry(const Hull& a, const Pose& pa, const Hull& b, const Pose& pb,
                                 double margin) {
  const std::vector<Vec2> va = placed_vertices(a, pa);
  const std::vector<Vec2> vb = placed_vertices(b, pb);
  const PlacedHull hull_a{va, a.radius};
  const PlacedHull hull_b{vb, b.radius};
  const CoreContact core = core_contact(core_of(hull_a), core_of(hull_b));
  ContactGeometry contact{
      core.distance - a.radius - b.radius, feature_normal(core.feature, hull_a, hull_b), {}};
  if (contact.distance > margin || (bare_line(a) && bare_line(b))) return contact;
  for (const Feature& f : clipped_features(core.feature, hull_a, hull_b)) {
    const double gap = feature_gap(f, hull_a, hull_b);
    // No pair that touches is deeper than the hulls overlap: a deeper one measures to a part of
    // an edge's line that the other hull does not reach (a steep edge, a line's end on a corner).
    const bool real = gap >= contact.distance - kRoundOff;
    if (real && gap <= margin) contact.points.push_back({feature_point(f, hull_a, hull_b), gap, f});
  }
  // The deepest pair is within the margin even where the clipped ends are not.
  if (contact.points.empty()) {
    contact.points.push_back({feature_point(core.feature, hull_a, hull_b),
                              feature_gap(core.feature, hull_a, hull_b), core.feature});
  }
  return contact;
}

}  // namespace gp::oracle
