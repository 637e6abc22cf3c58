// The peers are given our engine's mass, moment of inertia and centre of mass, and shapes placed
// where ours are: read back through each engine's own API.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

#include "engine/geometry/transform.hpp"
#include "peer_scenes.hpp"
#include "verification/peers/box2d_world.hpp"
#include "verification/peers/chipmunk_world.hpp"

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using gp::Vec2;

namespace {
namespace test_peer_mapping {

// A right triangle (legs 3 m and 1.5 m, centroid (1, 0.5) off the body origin), density
// 2 kg/m², at (1, 2) turned by 0.3 rad and spinning at 2 rad/s: m = 4.5 kg, centre of mass at
// (1, 2) + R(0.3)·(1, 0.5), I = m (a² + b²) / 18 = 2.8125 kg·m².
const std::array<Vec2, 3> kTriangle{Vec2{0.0, 0.0}, Vec2{3.0, 0.0}, Vec2{0.0, 1.5}};
const gp::Transform kPlacement({1.0, 2.0}, 0.3);

gp::Scene triangle_scene() {
  gp::Scene scene = gp::peers::testing::empty_scene(1.0 / 60.0);
  gp::BodyDef body;
  body.name = "triangle";
  body.position = kPlacement.position();
  body.angle = kPlacement.angle();
  body.angular_velocity = 2.0;
  body.shapes.push_back({gp::Shape::polygon(kTriangle), 0.0, 0.0, 2.0});
  scene.bodies.push_back(body);
  return scene;
}

const Vec2 kCenter = kPlacement.apply({1.0, 0.5});
constexpr double kMass = 4.5, kMoment = 4.5 * (9.0 + 2.25) / 18.0;

void visit_shape(cpBody*, cpShape* shape, void* out) {
  *static_cast<cpShape**>(out) = shape;
}

TEST_CASE("Chipmunk2D gets our mass, moment and centre of mass of an off-centre polygon",
          "[NFR:Correctness][peers]") {
  const gp::peers::ChipmunkWorld world(gp::peers::peer_scene(triangle_scene()));
  const cpBody* body = world.body(0);
  CHECK_THAT(cpBodyGetMass(body), WithinRel(kMass, 1e-12));
  CHECK_THAT(cpBodyGetMoment(body), WithinRel(kMoment, 1e-12));
  // Chipmunk2D is in double: criteria 3 to 10 times the error measured, or rounding (1e-15).
  CHECK_THAT(cpBodyGetPosition(body).x, WithinAbs(kCenter.x(), 1e-15));
  CHECK_THAT(cpBodyGetPosition(body).y, WithinAbs(kCenter.y(), 1e-15));
  CHECK(cpBodyGetCenterOfGravity(body).x == 0.0);
  CHECK(cpBodyGetCenterOfGravity(body).y == 0.0);
  cpShape* shape = nullptr;
  cpBodyEachShape(const_cast<cpBody*>(body), visit_shape, &shape);
  REQUIRE(cpPolyShapeGetCount(shape) == 3);
  for (int i = 0; i < 3; ++i) {
    const cpVect w = cpBodyLocalToWorld(body, cpPolyShapeGetVert(shape, i));
    const Vec2 expected = kPlacement.apply(kTriangle[i]);
    CHECK_THAT(w.x, WithinAbs(expected.x(), 2e-15));
    CHECK_THAT(w.y, WithinAbs(expected.y(), 2e-15));
  }
}

TEST_CASE("Box2D gets our mass, moment and centre of mass of an off-centre polygon",
          "[NFR:Correctness][peers]") {
  const gp::peers::Box2dWorld world(gp::peers::peer_scene(triangle_scene()));
  const b2Body* body = world.body(0);
  CHECK_THAT(body->GetMass(), WithinRel(kMass, 1e-6));
  CHECK_THAT(body->GetInertia(), WithinRel(kMoment, 1e-6));
  CHECK_THAT(body->GetWorldCenter().x, WithinAbs(kCenter.x(), 1e-6));
  CHECK_THAT(body->GetWorldCenter().y, WithinAbs(kCenter.y(), 1e-6));
  CHECK(body->GetLocalCenter().LengthSquared() == 0.0f);
  // The polygon is inset by Box2D's skin: every vertex lies b2_polygonRadius inside two of our
  // edges, so that the skin brings the outline back to ours.
  const auto* polygon = static_cast<const b2PolygonShape*>(body->GetFixtureList()->GetShape());
  REQUIRE(polygon->m_count == 3);
  for (int i = 0; i < 3; ++i) {
    const b2Vec2 w = body->GetWorldPoint(polygon->m_vertices[i]);
    int at_skin = 0;
    for (int e = 0; e < 3; ++e) {
      const Vec2 a = kPlacement.apply(kTriangle[e]);
      const Vec2 b = kPlacement.apply(kTriangle[(e + 1) % 3]);
      const Vec2 outward = Vec2(b.y() - a.y(), a.x() - b.x()).normalized();
      const double distance = outward.dot(Vec2(w.x, w.y) - a);
      CHECK(distance < 0.0);
      at_skin += std::abs(distance + b2_polygonRadius) < 1e-5;
    }
    CHECK(at_skin == 2);
  }
}

TEST_CASE("An off-centre polygon spins about our centre of mass in both peers",
          "[NFR:Correctness][peers]") {
  // No forces: a body that turns about its centre of mass keeps it still and keeps ω.
  const auto peer = gp::peers::peer_scene(triangle_scene());
  for (auto engine : {gp::peers::PeerEngine::Chipmunk, gp::peers::PeerEngine::Box2d}) {
    auto world = gp::peers::make_peer(engine, peer);
    for (int n = 0; n < 60; ++n) world->step(1.0 / 60.0);
    INFO(gp::peers::engine_name(engine));
    const gp::BodyState s = world->state(0);
    CHECK_THAT(s.position.x(), WithinAbs(kCenter.x(), 1e-5));
    CHECK_THAT(s.position.y(), WithinAbs(kCenter.y(), 1e-5));
    CHECK_THAT(s.angular_velocity, WithinAbs(2.0, 1e-5));
    CHECK_THAT(s.angle, WithinAbs(0.3 + 2.0, 1e-5));
  }
}

}  // namespace test_peer_mapping
}  // namespace
