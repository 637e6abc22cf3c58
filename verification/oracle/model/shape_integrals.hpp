#pragma once
// Area, centroid and second moment of area of each shape kind, written for the oracle from the
// closed forms (DD:ctrOfMass and DD:momentOfInertia take them per shape).

#include <span>

#include "gamephysics/models/types.hpp"

namespace gp::oracle {

/// A shape's geometry per unit density: times ρ [kg/m²] it gives the shape's mass ρ·area and its
/// moment of inertia about its own centroid ρ·polar_moment.
struct ShapeIntegrals {
  double area;          ///< m²
  Vec2 centroid;        ///< m
  double polar_moment;  ///< m⁴: ∫ |p − centroid|² dA
};

/// Disc of radius r: area π r², polar moment π r⁴ / 2.
ShapeIntegrals disc_integrals(const Vec2& center, double radius);

/// Convex polygon, counter-clockwise: a fan of triangles from the mean of its vertices, each with
/// area (a × b) / 2, centroid (a + b) / 3 and polar moment about the fan's centre
/// (a × b)(|a|² + a·b + |b|²) / 12; the sum moved to the centroid (parallel-axis theorem).
ShapeIntegrals polygon_integrals(std::span<const Vec2> vertices);

/// Segment a–b swept by a disc of radius r: a 2r × L rectangle and two half discs, each half disc
/// moved from its own centroid (4r / 3π off its flat side) to the middle of the segment. With r = 0
/// a bare line: area 0, polar moment 0, centroid the midpoint.
ShapeIntegrals capsule_integrals(const Vec2& a, const Vec2& b, double radius);

}  // namespace gp::oracle
