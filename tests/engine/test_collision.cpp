// Narrowphase contacts and signed distance between every pair of shape kinds
// (FR:Determine-Collisions, A:collisionType, LC:Expanded-Collisions).

#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "engine/collision/narrowphase.hpp"
#include "engine/collision/signed_distance.hpp"
#include "engine/geometry/closest_points.hpp"
#include "engine/geometry/world_shapes.hpp"

using gp::ContactManifold;
using gp::Shape;
using gp::Vec2;
using gp::WorldShape;

namespace {
namespace test_collision {

constexpr double kPi = std::numbers::pi;

WorldShape place(const Shape& shape, const Vec2& position, double angle = 0.0) {
  return gp::to_world(shape, gp::Transform(position, angle));
}

void check_near(const Vec2& actual, const Vec2& expected, double tolerance = 1e-12) {
  INFO("actual (" << actual.x() << ", " << actual.y() << "), expected (" << expected.x() << ", "
                  << expected.y() << ")");
  CHECK((actual - expected).norm() <= tolerance);
}

/// The manifold's point nearest to `position`.
const gp::ContactPoint& point_near(const ContactManifold& manifold, const Vec2& position) {
  REQUIRE(manifold.count > 0);
  const auto* best = &manifold.points[0];
  for (int i = 1; i < manifold.count; ++i) {
    if ((manifold.points[i].position - position).norm() < (best->position - position).norm()) {
      best = &manifold.points[i];
    }
  }
  return *best;
}

double deepest(const ContactManifold& manifold) {
  double depth = -INFINITY;
  for (int i = 0; i < manifold.count; ++i) depth = std::max(depth, manifold.points[i].depth);
  return depth;
}

/// collide(b, a) is collide(a, b) with the normal negated and the feature id halves swapped.
void check_swap_symmetric(const WorldShape& a, const WorldShape& b, double margin) {
  const ContactManifold ab = gp::collide(a, b, margin);
  const ContactManifold ba = gp::collide(b, a, margin);
  REQUIRE(ab.count == ba.count);
  if (ab.count == 0) return;
  check_near(ba.normal, -ab.normal);
  for (int i = 0; i < ab.count; ++i) {
    const gp::ContactPoint& p = ab.points[i];
    const gp::ContactPoint& q = point_near(ba, p.position);
    check_near(q.position, p.position);
    CHECK(q.depth == Approx(p.depth).margin(1e-12));
    CHECK(q.id.feature_a == p.id.feature_b);
    CHECK(q.id.feature_b == p.id.feature_a);
  }
}

const Shape kUnitBox = Shape::box(1.0, 1.0);
const Shape kGround = Shape::box(10.0, 1.0);
// Top face of the ground at y = 0.
const WorldShape kGroundPlaced = place(kGround, {0.0, -0.5});

TEST_CASE("Two unit circles 1.5 apart overlap by 0.5 along the line of centres",
          "[FR:Determine-Collisions]") {
  const WorldShape a = place(Shape::circle(1.0), {1.5, 0.0});
  const WorldShape b = place(Shape::circle(1.0), {0.0, 0.0});
  const ContactManifold manifold = gp::collide(a, b, 0.0);
  REQUIRE(manifold.count == 1);
  check_near(manifold.normal, {1.0, 0.0});  // from B towards A
  CHECK(manifold.points[0].depth == Approx(0.5).epsilon(1e-14));
  check_near(manifold.points[0].position, {0.75, 0.0});
  CHECK(gp::signed_distance(a, b) == Approx(-0.5).epsilon(1e-14));
}

TEST_CASE("Two discs collided from their centre gap touch along the line of centres",
          "[FR:Determine-Collisions]") {
  // By hand: centres (3, 4) and (0, 0) lie 5 apart, along (0.6, 0.8) from b towards a.
  const gp::CentreGap by_hand = gp::centre_gap({{3.0, 4.0}, 1.0}, {{0.0, 0.0}, 2.0});
  CHECK(by_hand.distance == 5.0);
  check_near(by_hand.direction, {0.6, 0.8}, 1e-15);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int touching = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const gp::Circle a{{unit(random), unit(random)}, 0.5 + 0.4 * unit(random)};
    // Every tenth pair concentric, where the gap has no direction and the normal is fixed.
    const gp::Circle b{trial % 10 == 0 ? a.center : Vec2(unit(random), unit(random)),
                       0.5 + 0.4 * unit(random)};
    const ContactManifold m = gp::collide_circles(a, b, gp::centre_gap(a, b), 0.05);
    // Each disc's surface point nearest the other lies its radius from its centre along the
    // line of centres; the contact point lies midway between them.
    const Vec2 offset = a.center - b.center;
    const double distance = std::hypot(offset.x(), offset.y());
    const double depth = a.radius + b.radius - distance;
    INFO("trial " << trial);
    REQUIRE(m.count == (depth >= -0.05 ? 1 : 0));
    touching += m.count;
    if (m.count == 0) continue;
    const Vec2 normal = distance > 0.0 ? Vec2(offset / distance) : Vec2(0.0, 1.0);
    check_near(m.normal, normal, 1e-15);
    CHECK(m.points[0].depth == Approx(depth).margin(1e-15));
    check_near(m.points[0].position,
               0.5 * (a.center - a.radius * normal + b.center + b.radius * normal), 1e-15);
  }
  CHECK(touching > 500);
}

TEST_CASE("A box resting on a box touches at its two bottom corners",
          "[FR:Determine-Collisions][LC:Expanded-Collisions]") {
  const WorldShape box = place(kUnitBox, {0.2, 0.45});  // sunk 0.05 into the ground
  const ContactManifold manifold = gp::collide(box, kGroundPlaced, 0.0);
  REQUIRE(manifold.count == 2);
  check_near(manifold.normal, {0.0, 1.0});
  // Midway between the box's bottom (y = −0.05) and the ground's top (y = 0).
  for (const Vec2& corner : {Vec2(-0.3, -0.025), Vec2(0.7, -0.025)}) {
    const gp::ContactPoint& point = point_near(manifold, corner);
    check_near(point.position, corner, 1e-12);
    CHECK(point.depth == Approx(0.05).epsilon(1e-12));
  }
  CHECK(manifold.points[0].id.key() != manifold.points[1].id.key());
  CHECK(gp::signed_distance(box, kGroundPlaced) == Approx(-0.05).epsilon(1e-12));
}

TEST_CASE("A tilted box's corner on the ground touches at one point",
          "[FR:Determine-Collisions][A:collisionType]") {
  // Turned 45°, its lowest corner is √2/2 below its centre: 0.1 into the ground.
  const WorldShape box = place(kUnitBox, {0.3, std::sqrt(0.5) - 0.1}, kPi / 4);
  const ContactManifold manifold = gp::collide(box, kGroundPlaced, 0.0);
  REQUIRE(manifold.count == 1);
  check_near(manifold.normal, {0.0, 1.0});
  CHECK(manifold.points[0].depth == Approx(0.1).epsilon(1e-12));
  check_near(manifold.points[0].position, {0.3, -0.05}, 1e-12);
  check_swap_symmetric(box, kGroundPlaced, 0.0);
}

TEST_CASE("Swapping the shapes negates the normal for every pair of kinds",
          "[FR:Determine-Collisions]") {
  const std::vector<std::pair<std::string, WorldShape>> shapes{
      {"circle", place(Shape::circle(0.6), {0.1, 0.2})},
      {"box", place(Shape::box(1.2, 0.8), {-0.3, 0.1}, 0.3)},
      {"triangle",
       place(Shape::polygon(std::vector<Vec2>{{0, 0}, {1.5, 0.2}, {0.4, 1.1}}), {-0.2, -0.6}, 1.1)},
      {"capsule", place(Shape::segment({-0.7, 0.0}, {0.8, 0.1}, 0.3), {0.2, -0.1}, 2.0)},
      {"line", place(Shape::segment({-1.0, 0.3}, {1.1, -0.2}), {0.0, 0.4}, -0.4)},
  };
  int contacts = 0;
  for (const auto& [name_a, a] : shapes) {
    for (const auto& [name_b, b] : shapes) {
      if (&a == &b) continue;
      INFO(name_a << " against " << name_b);
      check_swap_symmetric(a, b, 0.02);
      const ContactManifold manifold = gp::collide(a, b, 0.02);
      contacts += manifold.count > 0 ? 1 : 0;
      if (manifold.count > 0) CHECK(manifold.normal.norm() == Approx(1.0).epsilon(1e-12));
    }
  }
  CHECK(contacts == 20);  // placed so that every pair overlaps
}

TEST_CASE("A circle meets a polygon's face, its corner, or lies inside it",
          "[FR:Determine-Collisions]") {
  const WorldShape box = place(Shape::box(2.0, 2.0), {0.0, 0.0});
  SECTION("on the face") {
    const ContactManifold manifold = gp::collide(place(Shape::circle(0.5), {0.3, 1.4}), box, 0.0);
    REQUIRE(manifold.count == 1);
    check_near(manifold.normal, {0.0, 1.0});
    CHECK(manifold.points[0].depth == Approx(0.1).epsilon(1e-12));
    check_near(manifold.points[0].position, {0.3, 0.95});
  }
  SECTION("at the corner: the normal points from the corner to the centre") {
    const ContactManifold manifold = gp::collide(box, place(Shape::circle(0.6), {1.3, 1.4}), 0.0);
    REQUIRE(manifold.count == 1);
    check_near(manifold.normal, {-0.6, -0.8});  // from the circle (B) towards the box (A)
    CHECK(manifold.points[0].depth == Approx(0.1).epsilon(1e-12));
  }
  SECTION("centre inside: pushed out through the nearest face") {
    const WorldShape circle = place(Shape::circle(0.5), {0.8, 0.1});
    const ContactManifold manifold = gp::collide(circle, box, 0.0);
    REQUIRE(manifold.count == 1);
    check_near(manifold.normal, {1.0, 0.0});
    CHECK(manifold.points[0].depth == Approx(0.7).epsilon(1e-12));
    CHECK(gp::signed_distance(circle, box) == Approx(-0.7).epsilon(1e-12));
  }
}

TEST_CASE("A circle meets a segment along its side or beyond its end",
          "[FR:Determine-Collisions]") {
  const WorldShape capsule = place(Shape::segment({-1.0, 0.0}, {1.0, 0.0}, 0.1), {0.0, 0.0});
  SECTION("side") {
    const ContactManifold manifold =
        gp::collide(place(Shape::circle(0.5), {0.2, 0.5}), capsule, 0.0);
    REQUIRE(manifold.count == 1);
    check_near(manifold.normal, {0.0, 1.0});
    CHECK(manifold.points[0].depth == Approx(0.1).epsilon(1e-12));
    check_near(manifold.points[0].position, {0.2, 0.05});
  }
  SECTION("beyond the end") {
    const ContactManifold manifold =
        gp::collide(place(Shape::circle(0.5), {1.4, 0.0}), capsule, 0.0);
    REQUIRE(manifold.count == 1);
    check_near(manifold.normal, {1.0, 0.0});
    CHECK(manifold.points[0].depth == Approx(0.2).epsilon(1e-12));
  }
}

TEST_CASE("A capsule lying on a box touches at two points",
          "[FR:Determine-Collisions][LC:Expanded-Collisions]") {
  const WorldShape capsule = place(Shape::segment({-1.0, 0.0}, {1.0, 0.0}, 0.25), {0.0, 0.2});
  const WorldShape box = place(Shape::box(4.0, 1.0), {0.0, -0.5});
  const ContactManifold manifold = gp::collide(capsule, box, 0.0);
  REQUIRE(manifold.count == 2);
  check_near(manifold.normal, {0.0, 1.0});
  for (const Vec2& expected : {Vec2(-1.0, -0.025), Vec2(1.0, -0.025)}) {
    const gp::ContactPoint& point = point_near(manifold, expected);
    check_near(point.position, expected, 1e-12);
    CHECK(point.depth == Approx(0.05).epsilon(1e-12));
  }
}

TEST_CASE("A line poking into a box touches at its end", "[FR:Determine-Collisions]") {
  const WorldShape line = place(Shape::segment({0.0, -0.2}, {0.0, 1.0}), {0.0, 0.0});
  const WorldShape box = place(Shape::box(2.0, 2.0), {0.0, -1.0});
  const ContactManifold manifold = gp::collide(line, box, 0.0);
  REQUIRE(manifold.count == 1);
  check_near(manifold.normal, {0.0, 1.0});
  CHECK(manifold.points[0].depth == Approx(0.2).epsilon(1e-12));
  check_near(manifold.points[0].position, {0.0, -0.1});
}

TEST_CASE("Segments: bare lines never touch, capsules do", "[FR:Determine-Collisions]") {
  SECTION("crossing lines of radius 0 give no contact") {
    const WorldShape a = place(Shape::segment({-1.0, -1.0}, {1.0, 1.0}), {0.0, 0.0});
    const WorldShape b = place(Shape::segment({-1.0, 1.0}, {1.0, -1.0}), {0.0, 0.0});
    CHECK(gp::collide(a, b, 0.1).count == 0);
  }
  SECTION("parallel capsules side by side touch at two points") {
    const WorldShape a = place(Shape::segment({-1.0, 0.0}, {1.0, 0.0}, 0.2), {0.0, 0.3});
    const WorldShape b = place(Shape::segment({-0.5, 0.0}, {2.0, 0.0}, 0.2), {0.0, 0.0});
    const ContactManifold manifold = gp::collide(a, b, 0.0);
    REQUIRE(manifold.count == 2);
    check_near(manifold.normal, {0.0, 1.0});
    for (const Vec2& expected : {Vec2(-0.5, 0.15), Vec2(1.0, 0.15)}) {
      CHECK(point_near(manifold, expected).depth == Approx(0.1).epsilon(1e-12));
      check_near(point_near(manifold, expected).position, expected);
    }
  }
  SECTION("capsules end to end on one line touch along the line") {
    const WorldShape a = place(Shape::segment({1.3, 0.0}, {3.0, 0.0}, 0.2), {0.0, 0.0});
    const WorldShape b = place(Shape::segment({-1.0, 0.0}, {1.0, 0.0}, 0.2), {0.0, 0.0});
    const ContactManifold manifold = gp::collide(a, b, 0.0);
    REQUIRE(manifold.count == 1);
    check_near(manifold.normal, {1.0, 0.0});
    CHECK(manifold.points[0].depth == Approx(0.1).epsilon(1e-12));
    check_near(manifold.points[0].position, {1.15, 0.0});
    CHECK(gp::signed_distance(a, b) == Approx(-0.1).epsilon(1e-12));
  }
  SECTION("crossing capsules are pushed apart along a segment's normal") {
    const WorldShape a = place(Shape::segment({-1.0, -1.0}, {1.0, 1.0}, 0.1), {0.0, 0.0});
    const WorldShape b = place(Shape::segment({-1.0, 1.0}, {1.0, -1.0}, 0.1), {0.0, 0.0});
    const ContactManifold manifold = gp::collide(a, b, 0.0);
    REQUIRE(manifold.count >= 1);
    CHECK(std::abs(manifold.normal.x()) == Approx(std::sqrt(0.5)).epsilon(1e-12));
    CHECK(deepest(manifold) == Approx(std::sqrt(2.0) + 0.2).epsilon(1e-12));
    CHECK(gp::signed_distance(a, b) == Approx(-std::sqrt(2.0) - 0.2).epsilon(1e-12));
  }
}

TEST_CASE("Shapes apart by less than the margin give speculative points of negative depth",
          "[FR:Determine-Collisions]") {
  const WorldShape box = place(kUnitBox, {0.0, 0.52});  // 0.02 above the ground
  const ContactManifold near = gp::collide(box, kGroundPlaced, 0.05);
  REQUIRE(near.count == 2);
  CHECK(near.points[0].depth == Approx(-0.02).epsilon(1e-12));
  CHECK(near.points[1].depth == Approx(-0.02).epsilon(1e-12));
  CHECK(gp::collide(box, kGroundPlaced, 0.01).count == 0);

  const WorldShape a = place(Shape::circle(1.0), {2.1, 0.0});
  const WorldShape b = place(Shape::circle(1.0), {0.0, 0.0});
  REQUIRE(gp::collide(a, b, 0.2).count == 1);
  CHECK(gp::collide(a, b, 0.2).points[0].depth == Approx(-0.1).epsilon(1e-12));
  CHECK(gp::collide(a, b, 0.05).count == 0);
}

TEST_CASE("Feature ids stay the same while the same features touch", "[FR:Determine-Collisions]") {
  const ContactManifold before = gp::collide(place(kUnitBox, {0.2, 0.45}), kGroundPlaced, 0.0);
  const ContactManifold after =
      gp::collide(place(kUnitBox, {0.21, 0.449}, 0.001), kGroundPlaced, 0.0);
  REQUIRE(before.count == 2);
  REQUIRE(after.count == 2);
  for (int i = 0; i < before.count; ++i) {
    const gp::ContactPoint& moved = point_near(after, before.points[i].position);
    CHECK(moved.id == before.points[i].id);
    CHECK((moved.position - before.points[i].position).norm() < 0.02);
  }
}

TEST_CASE("Signed distance is the gap between shapes apart and minus the depth of overlap",
          "[FR:Determine-Collisions]") {
  SECTION("boxes apart corner to corner") {
    CHECK(gp::signed_distance(place(kUnitBox, {2.0, 2.0}), place(kUnitBox, {0.0, 0.0})) ==
          Approx(std::sqrt(2.0)).epsilon(1e-12));
  }
  SECTION("box apart from a circle, nearest at a corner") {
    CHECK(gp::signed_distance(place(kUnitBox, {0.0, 0.0}), place(Shape::circle(0.5), {3.5, 4.5})) ==
          Approx(4.5).epsilon(1e-12));
  }
  SECTION("circles apart") {
    CHECK(gp::signed_distance(place(Shape::circle(1.0), {3.0, 0.0}),
                              place(Shape::circle(1.0), {0.0, 0.0})) == Approx(1.0));
  }
  SECTION("parallel lines apart") {
    CHECK(gp::signed_distance(place(Shape::segment({0, 0}, {1, 0}), {0.0, 0.3}),
                              place(Shape::segment({3, 0}, {4, 0}), {0.0, 0.0})) ==
          Approx(std::hypot(2.0, 0.3)).epsilon(1e-12));
  }
}

// The outline of a placed polygon or segment as a closed chain of vertices (a segment's one
// edge is its chain's only edge), and its rounding radius [m].
struct Outline {
  std::vector<Vec2> vertices;
  bool closed;
  double radius;
};

Outline outline_of(const WorldShape& shape) {
  if (const auto* polygon = std::get_if<gp::ConvexPolygon>(&shape.geometry)) {
    return {{polygon->vertices.begin(), polygon->vertices.begin() + polygon->count}, true, 0.0};
  }
  const auto& segment = std::get<gp::Segment>(shape.geometry);
  return {{segment.a, segment.b}, false, segment.radius};
}

// The definition of the gap between outlines apart: the least distance from a vertex of either
// to an edge of the other, less both radii.
double gap_by_definition(const Outline& a, const Outline& b) {
  double squared = INFINITY;
  const auto measure = [&squared](const Outline& from, const Outline& to) {
    const std::size_t edges = to.closed ? to.vertices.size() : 1;
    for (const Vec2& v : from.vertices) {
      for (std::size_t i = 0; i < edges; ++i) {
        const Vec2 nearest = gp::closest_point_on_segment(
            v, to.vertices[i], to.vertices[(i + 1) % to.vertices.size()]);
        squared = std::min(squared, (v - nearest).squaredNorm());
      }
    }
  };
  measure(a, b);
  measure(b, a);
  return std::sqrt(squared) - a.radius - b.radius;
}

TEST_CASE("The gap between polygons and segments apart is the least vertex-to-edge gap, to the bit",
          "[FR:Determine-Collisions]") {
  const std::vector<Vec2> triangle{{0.0, 0.0}, {0.9, 0.1}, {0.2, 0.7}};
  const std::vector<Vec2> hexagon{{0.5, 0.0},  {0.25, 0.43},   {-0.25, 0.43},
                                  {-0.5, 0.0}, {-0.25, -0.43}, {0.25, -0.43}};
  const std::vector<Shape> shapes{Shape::box(1.0, 0.6),
                                  Shape::box(0.25, 0.25),
                                  Shape::polygon(triangle),
                                  Shape::polygon(hexagon),
                                  Shape::segment({-0.5, 0.0}, {0.5, 0.1}, 0.05),
                                  Shape::segment({0.0, 0.0}, {2.0, 0.0})};
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> offset(-1.5, 1.5);
  std::uniform_real_distribution<double> turn(0.0, 2 * kPi);
  std::uniform_int_distribution<std::size_t> pick(0, shapes.size() - 1);
  int apart = 0;
  int bounded = 0;  // answered by a bound
  // Near the origin, and 10 km from it, where a coordinate's round-off is a thousand times larger.
  for (const Vec2& origin : {Vec2(0.0, 0.0), Vec2(1e4, -1e4)}) {
    for (int i = 0; i < 20000; ++i) {
      const WorldShape a = place(shapes[pick(random)], origin, turn(random));
      const WorldShape b =
          place(shapes[pick(random)], origin + Vec2(offset(random), offset(random)), turn(random));
      const double gap = gp::signed_distance(a, b);
      // Asked only whether they are further apart than some length: the gap itself, or, where it
      // is surely longer, a bound that says so.
      const double asked = gap + offset(random);
      const double answer = gp::signed_distance(a, b, asked);
      CHECK((answer == gap || (answer > asked && gap > asked)));
      bounded += answer != gap ? 1 : 0;
      const Outline outline_a = outline_of(a);
      const Outline outline_b = outline_of(b);
      if (gap + outline_a.radius + outline_b.radius <= 0.0) continue;  // overlapping cores
      ++apart;
      CAPTURE(i, origin.x());
      if (!outline_a.closed && !outline_b.closed) {
        // Two segments are measured segment to segment, which rounds otherwise.
        REQUIRE(gap == Approx(gap_by_definition(outline_a, outline_b)).margin(1e-12));
      } else {
        REQUIRE(gap == gap_by_definition(outline_a, outline_b));
      }
    }
  }
  // Enough pairs apart to have met every shape against every other.
  CHECK(apart > 20000);
  CHECK(bounded > 1000);
}

TEST_CASE("Signed distance changes no faster than a shape moves and crosses zero on contact",
          "[FR:Determine-Collisions]") {
  const std::vector<Shape> shapes{Shape::circle(0.5), Shape::box(1.0, 0.6),
                                  Shape::segment({-0.6, 0.0}, {0.6, 0.1}, 0.2),
                                  Shape::segment({-0.6, 0.0}, {0.6, 0.1})};
  const double step = 0.01;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    for (std::size_t j = 0; j < shapes.size(); ++j) {
      INFO("shapes " << i << " and " << j);
      const WorldShape a = place(shapes[i], {0.0, 0.0}, 0.4);
      double previous = gp::signed_distance(a, place(shapes[j], {-3.0, 0.25}, -0.7));
      double lowest = previous;
      for (int k = 1; k <= 600; ++k) {
        const WorldShape b = place(shapes[j], {-3.0 + k * step, 0.25}, -0.7);
        const double distance = gp::signed_distance(a, b);
        CHECK(std::abs(distance - previous) <= step * (1.0 + 1e-9));
        CHECK(distance == Approx(gp::signed_distance(b, a)).margin(1e-12));
        lowest = std::min(lowest, distance);
        previous = distance;
      }
      CHECK(previous > 0.0);
      CHECK(lowest <= 0.0);
    }
  }
}

TEST_CASE("Contacts agree with the signed distance for random pairs of shapes",
          "[FR:Determine-Collisions]") {
  std::mt19937 random(20240611);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto random_shape = [&]() {
    switch (static_cast<int>(unit(random) * 5.0)) {
      case 0:
        return Shape::circle(0.2 + 0.8 * unit(random));
      case 1:
        return Shape::box(0.3 + 1.7 * unit(random), 0.3 + 1.7 * unit(random));
      case 2: {
        // Points on an ellipse, in angle order, are in convex position.
        const int count = 3 + static_cast<int>(unit(random) * 6.0);
        const double stretch = 0.4 + unit(random);
        std::vector<Vec2> vertices;
        for (int k = 0; k < count; ++k) {
          const double angle = (k + 0.6 * (unit(random) - 0.5)) * 2.0 * kPi / count;
          vertices.emplace_back(stretch * std::cos(angle), std::sin(angle));
        }
        return Shape::polygon(vertices);
      }
      case 3:
        return Shape::segment({-0.5 - unit(random), 0.0}, {0.5 + unit(random), 0.2 * unit(random)},
                              0.05 + 0.45 * unit(random));
      default:
        return Shape::segment({-0.5 - unit(random), 0.0}, {0.5 + unit(random), 0.0});
    }
  };
  const double margin = 0.05;
  int overlapping = 0;
  for (int trial = 0; trial < 5000; ++trial) {
    const WorldShape a = place(random_shape(), {0.0, 0.0}, 2.0 * kPi * unit(random));
    const WorldShape b = place(random_shape(), {4.0 * unit(random) - 2.0, 4.0 * unit(random) - 2.0},
                               2.0 * kPi * unit(random));
    const bool two_lines = a.kind() == gp::ShapeKind::kSegment &&
                           b.kind() == gp::ShapeKind::kSegment &&
                           std::get<gp::Segment>(a.geometry).radius == 0.0 &&
                           std::get<gp::Segment>(b.geometry).radius == 0.0;
    if (two_lines) continue;
    const double distance = gp::signed_distance(a, b);
    const ContactManifold manifold = gp::collide(a, b, margin);
    INFO("trial " << trial << ", kinds " << static_cast<int>(a.kind()) << " and "
                  << static_cast<int>(b.kind()) << ", signed distance " << distance);
    if (distance > margin + 1e-9) CHECK(manifold.count == 0);
    if (distance < -1e-9) {
      ++overlapping;
      REQUIRE(manifold.count >= 1);
      CHECK(manifold.normal.norm() == Approx(1.0).epsilon(1e-12));
      // The reference face may be A's while B's separates by up to kContactTolerance more.
      CHECK(deepest(manifold) == Approx(-distance).margin(gp::kContactTolerance + 1e-9));
    }
  }
  CHECK(overlapping > 1000);
}

TEST_CASE("Shapes as WorldShapes packs them collide as their views do, to the bit",
          "[FR:Determine-Collisions]") {
  // Boxes against boxes (the packed path's own), and every other pair of kinds (its fallback).
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const std::vector<Vec2> triangle{{0.0, 0.0}, {1.0, 0.0}, {0.3, 0.8}};
  const std::vector<Shape> shapes{kUnitBox, Shape::box(2.0, 0.5), Shape::circle(0.4),
                                  Shape::polygon(triangle),
                                  Shape::segment({-0.5, 0.0}, {0.5, 0.1}, 0.1)};
  const auto same_bits = [](double x, double y) {
    return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y);
  };
  int touching = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Shape& a = shapes[static_cast<std::size_t>(unit(random) * 5.0) % 5];
    const Shape& b = shapes[trial % 2 == 0 ? 0 : static_cast<std::size_t>(unit(random) * 5.0) % 5];
    gp::WorldShapes world;
    world.lay_out(2, 2, 8);
    world.place(0, gp::view_of(a.geometry()), gp::Transform({0.0, 0.0}, 6.3 * unit(random)));
    world.place(
        1, gp::view_of(b.geometry()),
        gp::Transform({2.0 * unit(random) - 1.0, 2.0 * unit(random) - 1.0}, 6.3 * unit(random)));
    const ContactManifold viewed = gp::collide(world.geometry(0), world.geometry(1), 0.05);
    const ContactManifold packed = gp::collide(world.packed(0), world.packed(1), 0.05);
    INFO("trial " << trial);
    REQUIRE(packed.count == viewed.count);
    touching += viewed.count > 0 ? 1 : 0;
    for (int k = 0; k < viewed.count; ++k) {
      CHECK(same_bits(packed.normal.x(), viewed.normal.x()));
      CHECK(same_bits(packed.normal.y(), viewed.normal.y()));
      CHECK(same_bits(packed.points[k].position.x(), viewed.points[k].position.x()));
      CHECK(same_bits(packed.points[k].position.y(), viewed.points[k].position.y()));
      CHECK(same_bits(packed.points[k].depth, viewed.points[k].depth));
      CHECK(packed.points[k].id == viewed.points[k].id);
    }
  }
  CHECK(touching > 1000);
}

}  // namespace test_collision
}  // namespace
