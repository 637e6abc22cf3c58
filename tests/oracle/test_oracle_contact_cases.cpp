// The oracle's contact geometry (verification/oracle/geometry) on cases worked by hand: a box
// resting flat on another, a box on its corner, two discs, a capsule sunk into a line, two crossing
// lines, a triangle sunk deep into a box's corner and two overlapping boxes.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "verification/oracle/geometry/contact_geometry.hpp"
#include "verification/oracle/model/world.hpp"

using Catch::Detail::Approx;
using gp::Shape;
using gp::Vec2;
using Kind = gp::oracle::Feature::Kind;
namespace oracle = gp::oracle;

namespace {
namespace test_oracle_contact_cases {

constexpr double kMargin = 0.02;  // m

oracle::Hull hull(const Shape& shape) {
  return oracle::hull_of(gp::ShapeDef{shape}, Vec2::Zero());
}

bool near(const Vec2& actual, const Vec2& expected) {
  return (actual - expected).norm() <= 1e-15;
}

TEST_CASE("Oracle contacts: cases worked by hand", "[oracle][geometry]") {
  SECTION("a 2 m box resting flat on a 4 m × 1 m box: two points at its bottom corners") {
    const auto contact =
        oracle::contact_geometry(hull(Shape::box(2, 2)), {{0.0, 1.5}, 0.0}, hull(Shape::box(4, 1)),
                                 {{0.0, 0.0}, 0.0}, kMargin);
    CHECK(contact.distance == 0.0);
    CHECK(near(contact.normal, {0.0, 1.0}));
    REQUIRE(contact.points.size() == 2);
    for (const auto& p : contact.points) {
      CHECK(p.separation == 0.0);
      CHECK(p.feature.kind == Kind::VertexEdge);
      CHECK(std::abs(p.point.x()) == 1.0);
      CHECK(p.point.y() == 0.5);
    }
  }
  SECTION("a unit box on its corner 0.1 m above a line: one point, under the corner") {
    const double half_diagonal = std::sqrt(0.5);
    const auto contact = oracle::contact_geometry(
        hull(Shape::box(1, 1)), {{0.0, half_diagonal + 0.1}, 0.25 * std::numbers::pi},
        hull(Shape::segment({-5, 0}, {5, 0})), {{0.0, 0.0}, 0.0}, 0.2);
    CHECK(contact.distance == Approx(0.1).epsilon(1e-15));
    CHECK(near(contact.normal, {0.0, 1.0}));
    REQUIRE(contact.points.size() == 1);
    // Midway between the corner at y = 0.1 and the line at y = 0.
    CHECK(contact.points[0].point.x() == Approx(0.0).margin(1e-15));
    CHECK(contact.points[0].point.y() == Approx(0.05).epsilon(1e-14));
  }
  SECTION("discs of radii 0.5 m and 1 m with centres 3 m apart: 1.5 m, the point at 1.75 m") {
    const auto contact = oracle::contact_geometry(hull(Shape::circle(0.5)), {{3.0, 0.0}, 0.0},
                                                  hull(Shape::circle(1.0)), {{0.0, 0.0}, 0.0}, 2.0);
    CHECK(contact.distance == 1.5);
    CHECK(near(contact.normal, {1.0, 0.0}));
    REQUIRE(contact.points.size() == 1);
    CHECK(contact.points[0].feature.kind == Kind::VertexVertex);
    CHECK(near(contact.points[0].point, {1.75, 0.0}));
    CHECK(contact.points[0].separation == 1.5);
    CHECK(oracle::contact_geometry(hull(Shape::circle(0.5)), {{3.0, 0.0}, 0.0},
                                   hull(Shape::circle(1.0)), {{0.0, 0.0}, 0.0}, kMargin)
              .points.empty());
  }
  SECTION("a capsule of radius 0.1 m lying 0.01 m deep in a line: two points at its ends") {
    const auto contact =
        oracle::contact_geometry(hull(Shape::segment({-1, 0}, {1, 0}, 0.1)), {{0.0, 0.09}, 0.0},
                                 hull(Shape::segment({-5, 0}, {5, 0})), {{0.0, 0.0}, 0.0}, kMargin);
    CHECK(contact.distance == Approx(-0.01).epsilon(1e-14));
    CHECK(near(contact.normal, {0.0, 1.0}));
    REQUIRE(contact.points.size() == 2);
    for (const auto& p : contact.points) {
      CHECK(p.separation == Approx(-0.01).epsilon(1e-14));
      CHECK(std::abs(p.point.x()) == 1.0);
      // Midway between the capsule's surface at −0.01 m and the line at 0.
      CHECK(p.point.y() == Approx(-0.005).epsilon(1e-13));
    }
  }
  SECTION("two crossing lines have no contact; their distance is the shorter way out, 0.5 m") {
    const auto line = hull(Shape::segment({-1, 0}, {1, 0}));
    const auto contact = oracle::contact_geometry(line, {{0.5, 0.0}, 0.5 * std::numbers::pi}, line,
                                                  {{0.0, 0.0}, 0.0}, kMargin);
    CHECK(contact.points.empty());
    CHECK(contact.distance == Approx(-0.5).epsilon(1e-15));
  }
  SECTION("a triangle sunk 0.9 m into a box's corner: the corner's foot is off the edge") {
    // The box's top y = 0 is the reference edge (the triangle's deepest vertex (1, −0.9) sets the
    // distance); the triangle's bottom edge from W = (1, −0.9) to (2.1, −0.6), direction
    // d = (1.1, 0.3), outward normal m = (0.3, −1.1)/√1.3, crosses the box's side x = 2. The
    // box's corner R = (2, 0) lies inside the triangle, and its foot on that edge's line,
    // (R − W)·d / |d|² = 1.37 / 1.3, falls off the edge's end: a deep overlap, whose depth at R
    // is still (R − W)·m = −0.69/√1.3, with the point R − gap·m / 2 (normal −m from the box).
    const std::vector<Vec2> triangle{{1.0, -0.9}, {2.1, -0.6}, {2.0, 1.0}};
    const auto contact =
        oracle::contact_geometry(hull(Shape::polygon(triangle)), {{0, 0}, 0.0},
                                 hull(Shape::box(4, 2)), {{0.0, -1.0}, 0.0}, kMargin);
    CHECK(contact.distance == Approx(-0.9).epsilon(1e-15));
    CHECK(near(contact.normal, {0.0, 1.0}));
    REQUIRE(contact.points.size() == 2);
    const auto& corner = contact.points[1];
    CHECK(corner.feature.kind == Kind::EdgeVertex);
    CHECK(corner.separation == Approx(-0.69 / std::sqrt(1.3)).epsilon(1e-15));
    CHECK(corner.point.x() == Approx(2.0 + 0.345 * 0.3 / 1.3).epsilon(1e-15));
    CHECK(corner.point.y() == Approx(-0.345 * 1.1 / 1.3).epsilon(1e-15));
    // The triangle's deepest vertex against the top: 0.9 m deep, midway at y = −0.45.
    CHECK(contact.points[0].separation == Approx(-0.9).epsilon(1e-15));
    CHECK(near(contact.points[0].point, {1.0, -0.45}));
  }
  SECTION("two 2 m boxes overlapping 0.5 m in x and 1.8 m in y: depth 0.5 m along x") {
    const auto box = hull(Shape::box(2, 2));
    CHECK(oracle::signed_distance(box, {{1.5, 0.2}, 0.0}, box, {{0.0, 0.0}, 0.0}) == -0.5);
    const auto contact =
        oracle::contact_geometry(box, {{1.5, 0.2}, 0.0}, box, {{0.0, 0.0}, 0.0}, kMargin);
    CHECK(near(contact.normal, {1.0, 0.0}));
  }
}

}  // namespace test_oracle_contact_cases
}  // namespace
