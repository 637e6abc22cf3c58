// Shapes, their validation, mass properties and placement in the world (FR:Determine-Collisions).

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include "engine/collision/body_shapes.hpp"
#include "engine/geometry/mass_properties.hpp"
#include "engine/geometry/shape_extent.hpp"
#include "engine/geometry/world_bounds.hpp"
#include "engine/geometry/world_shape.hpp"
#include "engine/geometry/world_shapes.hpp"

using gp::Shape;
using gp::Vec2;

namespace {
namespace test_shape {

constexpr double kPi = std::numbers::pi;

void check_near(const Vec2& actual, const Vec2& expected, double tolerance = 1e-12) {
  INFO("actual (" << actual.x() << ", " << actual.y() << "), expected (" << expected.x() << ", "
                  << expected.y() << ")");
  CHECK((actual - expected).norm() <= tolerance);
}

// A box off the centre of mass, an offset disc, a rounded segment and a triangle.
std::vector<Shape> one_of_each_kind() {
  return {Shape::box(2.0, 1.0, {1.0, 0.0}), Shape::circle(0.5, {0.3, 0.1}),
          Shape::segment({-1.0, 0.5}, {2.0, -0.25}, 0.05),
          Shape::polygon(std::vector<Vec2>{{0, 0}, {1, 0}, {0.2, 1}})};
}

gp::BodyShapes on_one_body(const std::vector<Shape>& shapes) {
  gp::BodyShapes records;
  for (const Shape& shape : shapes) records.add(0, shape, 0.0, 0.5, true);
  return records;
}

gp::ConvexPolygon polygon_of(const Shape& shape) {
  return std::get<gp::ConvexPolygon>(shape.geometry());
}

TEST_CASE("A unit square has area 1, centroid at its centre and polar moment 1/6",
          "[FR:Determine-Collisions]") {
  const std::vector<Vec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const gp::MassProperties mass = gp::mass_properties(Shape::polygon(square));
  CHECK(mass.area == Approx(1.0).epsilon(1e-14));
  check_near(mass.centroid, {0.5, 0.5});
  // ∫(x² + y²) over [−½, ½]²  = 2 · (1/12).
  CHECK(mass.polar_moment == Approx(1.0 / 6.0).epsilon(1e-14));
}

TEST_CASE("A box w × h at an offset has area w h and polar moment w h (w² + h²) / 12",
          "[FR:Determine-Collisions]") {
  const gp::MassProperties mass = gp::mass_properties(Shape::box(2.0, 3.0, {1.0, -2.0}));
  CHECK(mass.area == Approx(6.0).epsilon(1e-14));
  check_near(mass.centroid, {1.0, -2.0});
  CHECK(mass.polar_moment == Approx(6.0 * 13.0 / 12.0).epsilon(1e-14));
}

TEST_CASE("A triangle's polar moment about its centroid is A (a² + b² + c²) / 36",
          "[FR:Determine-Collisions]") {
  const std::vector<Vec2> right_triangle{{0, 0}, {3, 0}, {0, 4}};  // sides 3, 4, 5
  const gp::MassProperties mass = gp::mass_properties(Shape::polygon(right_triangle));
  CHECK(mass.area == Approx(6.0).epsilon(1e-14));
  check_near(mass.centroid, {1.0, 4.0 / 3.0});
  CHECK(mass.polar_moment == Approx(6.0 * (9.0 + 16.0 + 25.0) / 36.0).epsilon(1e-14));
}

TEST_CASE("A regular hexagon far from the origin has area 3√3/2 a² and polar moment 5√3/8 a⁴",
          "[FR:Determine-Collisions]") {
  const double side = 0.7;
  const Vec2 center(300.0, -400.0);
  std::vector<Vec2> hexagon;
  for (int k = 0; k < 6; ++k) {
    hexagon.push_back(center + side * Vec2(std::cos(k * kPi / 3), std::sin(k * kPi / 3)));
  }
  const gp::MassProperties mass = gp::mass_properties(Shape::polygon(hexagon));
  CHECK(mass.area == Approx(1.5 * std::sqrt(3.0) * side * side).epsilon(1e-12));
  check_near(mass.centroid, center, 1e-10);
  CHECK(mass.polar_moment == Approx(5.0 * std::sqrt(3.0) / 8.0 * std::pow(side, 4)).epsilon(1e-9));
}

TEST_CASE("A circle has area π r² and polar moment π r⁴ / 2 about its centre",
          "[FR:Determine-Collisions]") {
  const gp::MassProperties mass = gp::mass_properties(Shape::circle(2.0, {1.0, -1.0}));
  CHECK(mass.area == Approx(4.0 * kPi).epsilon(1e-14));
  check_near(mass.centroid, {1.0, -1.0});
  CHECK(mass.polar_moment == Approx(8.0 * kPi).epsilon(1e-14));
}

TEST_CASE("A capsule's closed-form mass properties match integrating over its area",
          "[FR:Determine-Collisions]") {
  const double radius = 0.5;
  const Vec2 a(-1.0, 0.0);
  const Vec2 b(1.0, 0.0);
  const gp::MassProperties mass = gp::mass_properties(Shape::segment(a, b, radius));

  // Midpoint rule over the bounding box, a point counting when it is within `radius` of the core.
  const double step = 1e-3;
  double area = 0.0;
  double polar = 0.0;
  for (double x = -1.5 + 0.5 * step; x < 1.5; x += step) {
    for (double y = -0.5 + 0.5 * step; y < 0.5; y += step) {
      const double along = std::clamp(x, -1.0, 1.0);
      if (std::hypot(x - along, y) <= radius) {
        area += step * step;
        polar += (x * x + y * y) * step * step;
      }
    }
  }
  CHECK(mass.area == Approx(2.0 * radius * 2.0 + kPi * radius * radius).epsilon(1e-14));
  CHECK(mass.area == Approx(area).epsilon(1e-4));
  check_near(mass.centroid, {0.0, 0.0});
  CHECK(mass.polar_moment == Approx(polar).epsilon(1e-4));
}

TEST_CASE("A segment of radius 0 has no area and no polar moment, and its midpoint as centroid",
          "[FR:Determine-Collisions]") {
  const gp::MassProperties mass = gp::mass_properties(Shape::segment({1.0, 2.0}, {3.0, 6.0}));
  CHECK(mass.area == 0.0);
  CHECK(mass.polar_moment == 0.0);
  check_near(mass.centroid, {2.0, 4.0});
}

TEST_CASE("A clockwise polygon is reordered counter-clockwise with outward unit normals",
          "[FR:Determine-Collisions]") {
  const std::vector<Vec2> clockwise{{0, 0}, {0, 2}, {1, 2}, {1, 0}};
  const gp::ConvexPolygon polygon = polygon_of(Shape::polygon(clockwise));
  REQUIRE(polygon.count == 4);
  double twice_area = 0.0;
  for (int i = 0; i < polygon.count; ++i) {
    const Vec2& start = polygon.vertices[i];
    const Vec2& end = polygon.vertices[(i + 1) % polygon.count];
    twice_area += gp::cross(start, end);
    CHECK(polygon.normals[i].norm() == Approx(1.0).epsilon(1e-15));
    CHECK(std::abs(polygon.normals[i].dot(end - start)) <= 1e-15);
    for (int k = 0; k < polygon.count; ++k)
      CHECK(polygon.normals[i].dot(polygon.vertices[k] - start) <= 1e-15);
  }
  CHECK(twice_area == Approx(4.0));
  for (const Vec2& v : clockwise) {
    bool kept = false;
    for (int i = 0; i < polygon.count; ++i) kept = kept || polygon.vertices[i] == v;
    CHECK(kept);
  }
}

TEST_CASE("Repeated consecutive vertices of a polygon are merged", "[FR:Determine-Collisions]") {
  const std::vector<Vec2> repeated{{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
  const Shape merged = Shape::polygon(repeated);
  CHECK(polygon_of(merged).count == 4);
  // The unit square's mass properties: area 1, centroid (½, ½), polar moment 1/6.
  const gp::MassProperties mass = gp::mass_properties(merged);
  CHECK(mass.area == Approx(1.0).epsilon(1e-14));
  check_near(mass.centroid, {0.5, 0.5});
  CHECK(mass.polar_moment == Approx(1.0 / 6.0).epsilon(1e-14));
}

TEST_CASE("Polygons breaking a rule are rejected with the rule and the value",
          "[FR:Determine-Collisions]") {
  const auto rejects = [](const std::vector<Vec2>& vertices, const std::string& message) {
    INFO(message);
    CHECK_THROWS_AS(Shape::polygon(vertices), std::invalid_argument);
    CHECK_THROWS_WITH(Shape::polygon(vertices), Catch::Contains(message));
  };
  SECTION("non-convex") {
    rejects({{0, 0}, {2, 0}, {2, 2}, {1, 0.5}, {0, 2}},
            "strictly convex (no reflex or straight corner): vertex (1, 0.5) is not");
  }
  SECTION("self-intersecting star, whose turns all bend the same way") {
    std::vector<Vec2> star;
    for (int k = 0; k < 5; ++k)
      star.emplace_back(std::cos(k * 4 * kPi / 5), std::sin(k * 4 * kPi / 5));
    rejects(star, "must not intersect itself");
  }
  SECTION("a vertex in the middle of an edge") {
    rejects({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}},
            "strictly convex (no reflex or straight corner): vertex (1, 0) is not");
  }
  SECTION("collinear") {
    rejects({{0, 0}, {1, 1}, {3, 3}}, "area must be > 0");
  }
  SECTION("a vertex repeated away from its neighbour, so the outline crosses itself") {
    rejects({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {2, 0}}, "strictly convex");
  }
  SECTION("fewer than 3 distinct vertices") {
    rejects({{0, 0}, {1, 1}, {1, 1}, {0, 0}}, "at least 3 distinct vertices, got 2");
  }
  SECTION("more vertices than the fixed capacity") {
    std::vector<Vec2> nonagon;
    for (int k = 0; k < 9; ++k)
      nonagon.emplace_back(std::cos(k * 2 * kPi / 9), std::sin(k * 2 * kPi / 9));
    rejects(nonagon, "at most 8 vertices, got 9");
  }
  SECTION("not finite") {
    rejects({{0, 0}, {1, 0}, {std::nan(""), 1}}, "polygon vertex 2 must be finite, got (nan, 1)");
  }
}

TEST_CASE("Circles, boxes and segments breaking a rule are rejected with the rule and the value",
          "[FR:Determine-Collisions]") {
  CHECK_THROWS_AS(Shape::circle(0.0), std::invalid_argument);
  CHECK_THROWS_WITH(Shape::circle(-1.0), Catch::Contains("radius must be finite and > 0, got -1"));
  CHECK_THROWS_WITH(Shape::circle(INFINITY), Catch::Contains("got inf"));
  CHECK_THROWS_WITH(Shape::circle(1.0, {NAN, 0.0}),
                    Catch::Contains("circle centre must be finite"));
  CHECK_THROWS_WITH(Shape::box(0.0, 1.0),
                    Catch::Contains("box width must be finite and > 0, got 0"));
  CHECK_THROWS_WITH(Shape::box(1.0, -2.0),
                    Catch::Contains("box height must be finite and > 0, got -2"));
  CHECK_THROWS_WITH(Shape::segment({0, 0}, {1, 0}, -0.1),
                    Catch::Contains("segment radius must be finite and >= 0, got -0.1"));
  CHECK_THROWS_WITH(Shape::segment({1, 2}, {1, 2}, 0.5), Catch::Contains("ends must be distinct"));
  CHECK_NOTHROW(Shape::segment({0, 0}, {1, 0}, 0.0));
}

TEST_CASE("A shape placed by a transform has its vertices, normals and bounds moved with it",
          "[FR:Determine-Collisions]") {
  const gp::Transform quarter_turn({3.0, 4.0}, kPi / 2);
  SECTION("box") {
    const gp::WorldShape box = gp::to_world(Shape::box(2.0, 1.0, {1.0, 0.0}), quarter_turn);
    const auto& polygon = std::get<gp::ConvexPolygon>(box.geometry);
    // Body corners (0, −½), (2, −½), (2, ½), (0, ½) turned a quarter: (x, y) → (−y, x).
    check_near(polygon.vertices[0], {3.5, 4.0});
    check_near(polygon.vertices[1], {3.5, 6.0});
    check_near(polygon.vertices[2], {2.5, 6.0});
    check_near(polygon.vertices[3], {2.5, 4.0});
    check_near(polygon.normals[0], {1.0, 0.0});
    check_near(polygon.normals[1], {0.0, 1.0});
    check_near(box.bounds.min, {2.5, 4.0});
    check_near(box.bounds.max, {3.5, 6.0});
    CHECK(box.kind() == gp::ShapeKind::kPolygon);
  }
  SECTION("circle") {
    const gp::WorldShape circle = gp::to_world(Shape::circle(0.5, {1.0, 0.0}), quarter_turn);
    check_near(std::get<gp::Circle>(circle.geometry).center, {3.0, 5.0});
    check_near(circle.bounds.min, {2.5, 4.5});
    check_near(circle.bounds.max, {3.5, 5.5});
  }
  SECTION("capsule") {
    const gp::WorldShape capsule =
        gp::to_world(Shape::segment({0.0, 0.0}, {2.0, 0.0}, 0.25), quarter_turn);
    check_near(std::get<gp::Segment>(capsule.geometry).b, {3.0, 6.0});
    check_near(capsule.bounds.min, {2.75, 3.75});
    check_near(capsule.bounds.max, {3.25, 6.25});
  }
}

TEST_CASE("A shape made again from a view of its geometry has the same numbers",
          "[FR:Determine-Collisions]") {
  const std::vector<Vec2> pentagon{{0.1, -0.3}, {1.7, 0.2}, {1.9, 1.3}, {0.6, 2.1}, {-0.8, 0.9}};
  const Shape polygon = Shape::polygon(pentagon);
  const gp::ConvexPolygon again = polygon_of(Shape::copy_of(gp::view_of(polygon.geometry())));
  REQUIRE(again.count == 5);
  for (int i = 0; i < 5; ++i) {
    CHECK(again.vertices[i] == polygon_of(polygon).vertices[i]);
    CHECK(again.normals[i] == polygon_of(polygon).normals[i]);
  }
  const Shape circle = Shape::circle(0.3, {0.1, 0.2});
  const auto disc = std::get<gp::Circle>(Shape::copy_of(gp::view_of(circle.geometry())).geometry());
  CHECK(disc.center == Vec2(0.1, 0.2));
  CHECK(disc.radius == 0.3);
  const Shape capsule = Shape::segment({0.0, 1.0}, {2.0, 3.0}, 0.1);
  const auto line =
      std::get<gp::Segment>(Shape::copy_of(gp::view_of(capsule.geometry())).geometry());
  CHECK(line.a == Vec2(0.0, 1.0));
  CHECK(line.b == Vec2(2.0, 3.0));
  CHECK(line.radius == 0.1);
}

TEST_CASE("Shapes placed in one pool are placed as one by one, and keep their room",
          "[FR:Determine-Collisions]") {
  const std::vector<Shape> shapes{Shape::box(2.0, 1.0, {1.0, 0.0}), Shape::circle(0.5),
                                  Shape::polygon(std::vector<Vec2>{{0, 0}, {1, 0}, {0, 1}})};
  const gp::Transform frame({3.0, 4.0}, 0.7);
  gp::WorldShapes world;
  world.lay_out(shapes.size(), 2, 7);
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    world.place(i, gp::view_of(shapes[i].geometry()), frame);
  }
  const auto* box_room = std::get<gp::PolygonView>(world[0].geometry).vertices.data();
  world.place(0, gp::view_of(shapes[0].geometry()), gp::Transform({1.0, 1.0}, 0.2));
  CHECK(std::get<gp::PolygonView>(world[0].geometry).vertices.data() == box_room);
  world.place(0, gp::view_of(shapes[0].geometry()), frame);
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    const gp::WorldShape alone = gp::to_world(shapes[i], frame);
    CHECK(world[i].kind() == alone.kind());
    CHECK(world[i].bounds.min == alone.bounds.min);
    CHECK(world[i].bounds.max == alone.bounds.max);
  }
  const auto triangle = std::get<gp::PolygonView>(world[2].geometry);
  const gp::WorldShape alone = gp::to_world(shapes[2], frame);
  const auto& expected = std::get<gp::ConvexPolygon>(alone.geometry);
  REQUIRE(triangle.vertices.size() == 3);
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(triangle.vertices[i] == expected.vertices[i]);
    CHECK(triangle.normals[i] == expected.normals[i]);
  }
  // More polygon vertices than laid out would move the pool under the views already given.
  gp::WorldShapes small;
  small.lay_out(1, 1, 3);
  CHECK_THROWS_AS(small.place(0, gp::view_of(shapes[0].geometry()), frame), std::logic_error);
}

TEST_CASE("A shape's box placed alone is the box of the shape placed whole, bit for bit",
          "[FR:Determine-Collisions]") {
  const std::vector<Shape> shapes = one_of_each_kind();
  const gp::BodyShapes records = on_one_body(shapes);
  gp::WorldBounds boxes;
  boxes.lay_out(shapes.size());
  for (int k = 0; k < 200; ++k) {
    const double angle = 0.0314159 * k - 3.0;
    const gp::Transform frame({std::cos(0.7 * k) * 1e3, 1e-3 * k}, angle);
    for (std::size_t i = 0; i < shapes.size(); ++i) {
      boxes.place(i, records[i].local, frame);
      const gp::WorldShape whole = gp::to_world(shapes[i], frame);
      CHECK(boxes.bounds(i).min == whole.bounds.min);
      CHECK(boxes.bounds(i).max == whole.bounds.max);
    }
    // The 2 m × 1 m box about (1, 0) in closed form: its centre moved, half-extents |cos|·1 +
    // |sin|·0.5 across and |sin|·1 + |cos|·0.5 up.
    const Vec2 centre = frame.apply({1.0, 0.0});
    const Vec2 half(std::abs(std::cos(angle)) + 0.5 * std::abs(std::sin(angle)),
                    std::abs(std::sin(angle)) + 0.5 * std::abs(std::cos(angle)));
    CHECK((boxes.bounds(0).min - (centre - half)).norm() < 1e-9);
    CHECK((boxes.bounds(0).max - (centre + half)).norm() < 1e-9);
  }
}

TEST_CASE("A shape's farthest point from its body's centre of mass, with and without its radius",
          "[FR:Determine-Collisions]") {
  gp::BodyShapes records;
  records.add(0, Shape::box(2.0, 1.0, {1.0, 0.0}), 0.0, 0.5, true);
  records.add(0, Shape::circle(0.5, {0.3, -0.4}), 0.0, 0.5, true);
  records.add(0, Shape::circle(0.5), 0.0, 0.5, true);
  records.add(0, Shape::segment({-1.0, 0.5}, {2.0, -0.25}, 0.05), 0.0, 0.5, true);
  // By hand: the corners (2, ±0.5); the centre (0.3, −0.4); the end (2, −0.25).
  CHECK(gp::core_reach(records[0].local) == Approx(std::sqrt(4.25)).epsilon(1e-15));
  CHECK(gp::core_reach(records[1].local) == Approx(0.5).epsilon(1e-15));
  CHECK(gp::core_reach(records[2].local) == 0.0);
  CHECK(gp::core_reach(records[3].local) == Approx(std::sqrt(4.0625)).epsilon(1e-15));
  // reach() adds the radius: the whole shape's farthest point.
  CHECK(gp::reach(records[0].local) == Approx(std::sqrt(4.25)).epsilon(1e-15));
  CHECK(gp::reach(records[1].local) == Approx(1.0).epsilon(1e-15));
  CHECK(gp::reach(records[2].local) == 0.5);
  CHECK(gp::reach(records[3].local) == Approx(std::sqrt(4.0625) + 0.05).epsilon(1e-15));
  // Each record keeps it as a float at or above it.
  for (std::size_t i = 0; i < records.size(); ++i) {
    const double reach = gp::core_reach(records[i].local);
    CHECK(static_cast<double>(records[i].core_reach) >= reach);
    CHECK(static_cast<double>(records[i].core_reach) <= reach * (1.0 + 1e-7));
  }
  // And a shape's stays its own when shapes before it are removed: a unit box's corner, √0.5.
  records.add(1, Shape::box(1.0, 1.0), 0.0, 0.5, true);
  records.remove_body(0);
  REQUIRE(records.size() == 1);
  CHECK(static_cast<double>(records[0].core_reach) == Approx(std::sqrt(0.5)).epsilon(1e-7));
}

TEST_CASE("A shape's box moved from the start holds the shape moved and turned, and little more",
          "[FR:Determine-Collisions]") {
  const std::vector<Shape> shapes = one_of_each_kind();
  const gp::BodyShapes records = on_one_body(shapes);
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  // Turns from none to more than a whole turn, the larger ones rarer.
  const std::vector<double> turn_scales{0.0, 1e-9, 1e-3, 0.1, 3.0, 10.0};
  for (int k = 0; k < 2000; ++k) {
    const Vec2 from(1e3 * unit(random), 10.0 * unit(random));
    const double angle = kPi * (1.0 + unit(random));
    const double turn =
        turn_scales[static_cast<std::size_t>(k) % turn_scales.size()] * unit(random);
    const Vec2 to = from + Vec2(unit(random), unit(random));
    for (std::size_t i = 0; i < shapes.size(); ++i) {
      const gp::PackedGeometry& local = records[i].local;
      const gp::Aabb start = gp::placed_bounds(local, gp::Transform(from, angle));
      const gp::Aabb end = gp::placed_bounds(local, gp::Transform(to, angle + turn));
      const double reach = gp::core_reach(local);
      const gp::Aabb moved = gp::moved_bounds(start, to - from, turn, reach);
      INFO("shape " << i << ", turn " << turn);
      CHECK((moved.min.array() <= end.min.array()).all());
      CHECK((moved.max.array() >= end.max.array()).all());
      // Each side within the two boxes' moves, |turn| · reach each (at most 2 reach), of the
      // tight one.
      const double looser = 2.0 * std::min(std::abs(turn), 2.0) * reach + 1e-9;
      CHECK(((end.min - moved.min).array() <= looser).all());
      CHECK(((moved.max - end.max).array() <= looser).all());
    }
  }
}

TEST_CASE("Identical polygons added one after another share their vertices",
          "[FR:Determine-Collisions]") {
  gp::BodyShapes records;
  records.add(0, Shape::box(1.0, 1.0), 0.0, 0.5, true);
  records.add(1, Shape::box(1.0, 1.0), 0.0, 0.5, true);
  records.add(2, Shape::box(1.0, 2.0), 0.0, 0.5, true);
  records.add(3, Shape::box(1.0, 2.0), 0.0, 0.5, true);
  const auto vertices = [&](std::size_t i) { return records[i].local.polygon().vertices; };
  CHECK(vertices(0).data() == vertices(1).data());
  CHECK(vertices(1).data() != vertices(2).data());
  CHECK(vertices(2).data() == vertices(3).data());
  // A shared block outlives the shapes it was made for, and is shared no more after a removal.
  records.remove_body(2);
  records.remove_body(0);
  records.add(4, Shape::box(1.0, 2.0), 0.0, 0.5, true);
  REQUIRE(records.size() == 3);
  CHECK(vertices(1).data() != vertices(2).data());
  const gp::WorldShape kept = gp::to_world(records[1].local, gp::Transform({0.0, 0.0}));
  const gp::WorldShape fresh = gp::to_world(Shape::box(1.0, 2.0), gp::Transform({0.0, 0.0}));
  CHECK(kept.bounds.min == fresh.bounds.min);
  CHECK(kept.bounds.max == fresh.bounds.max);
  CHECK(kept.bounds.min == Vec2(-0.5, -1.0));
}

}  // namespace test_shape
}  // namespace
