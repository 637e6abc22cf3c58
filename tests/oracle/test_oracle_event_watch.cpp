// The oracle's root functions (verification/oracle/hybrid/event_watch) on a case worked by hand:
// a capsule's end touching a box's corner, corner on corner, must be watched leaving either
// corner's normal cone.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "scene/scene.hpp"
#include "verification/oracle/contact/active_contact.hpp"
#include "verification/oracle/geometry/contact_geometry.hpp"
#include "verification/oracle/hybrid/event_watch.hpp"
#include "verification/oracle/hybrid/hybrid_system.hpp"
#include "verification/oracle/model/world.hpp"

using gp::BodyDef;
using gp::Shape;
using gp::Vec2;
namespace oracle = gp::oracle;

namespace {
namespace test_oracle_event_watch {

constexpr double kRadius = 0.1;  // m: the capsule's
constexpr double kPi = std::numbers::pi;

// The capsule (2 m long, its centre of mass at its middle) with its right end at `end` and its
// axis at angle `angle` [rad]: its centre is 1 m back along the axis.
oracle::Motion capsule_at(const Vec2& end, double angle) {
  return {end - Vec2(std::cos(angle), std::sin(angle)), angle, Vec2::Zero(), 0.0};
}

// The least OffCorner root of the corner's sides 0, 1 (the second's) or 2, 3 (the first's), at
// `motions`, with `contact` armed at `armed`.
struct CornerRoots {
  double second = INFINITY;
  double first = INFINITY;
};

CornerRoots corner_roots(const oracle::World& world, const oracle::ActiveContact& contact,
                         const std::vector<oracle::Motion>& armed,
                         const std::vector<oracle::Motion>& motions) {
  oracle::EventWatch watch(world, 1e-9, 1e-9);
  const std::vector<oracle::ActiveContact> contacts{contact};
  watch.arm(contacts, armed);
  oracle::HybridSystem system(world);
  system.set_contacts(contacts);
  oracle::Snapshot snapshot;
  system.evaluate(0.0, motions, snapshot);
  std::vector<double> g(watch.size());
  watch.evaluate(snapshot, contacts, g.data());
  CornerRoots least;
  for (std::size_t r = 0; r < watch.size(); ++r) {
    if (watch.root(r).kind != oracle::RootKind::OffCorner) continue;
    double& side = watch.root(r).detail < 2 ? least.second : least.first;
    side = std::min(side, g[r]);
  }
  return least;
}

TEST_CASE("Oracle events: a corner-on-corner contact watches both corners' normal cones",
          "[oracle][events]") {
  // Body 0 (the contact's first): a horizontal capsule whose right end touches the top-left
  // corner (−0.5, 0.5) of body 1, a unit box at the origin, along the diagonal n = (−1, 1)/√2:
  // inside the box's corner cone (between (−1, 0) and (0, 1)) and inside the end's cone (−n
  // points along +x, ahead of the end).
  BodyDef capsule;
  capsule.name = "capsule";
  capsule.shapes.push_back({Shape::segment({-1.0, 0.0}, {1.0, 0.0}, kRadius)});
  BodyDef box;
  box.name = "box";
  box.shapes.push_back({Shape::box(1.0, 1.0)});
  gp::Scene scene{{}, 0.01, 1.0, 0.01, {capsule, box}};
  const oracle::World world = oracle::build_world(scene);
  const Vec2 corner(-0.5, 0.5);
  const Vec2 end = corner + kRadius * Vec2(-1.0, 1.0) / std::sqrt(2.0);
  const std::vector<oracle::Motion> touching = {capsule_at(end, 0.0), world.bodies[1].initial};

  const auto geometry =
      oracle::contact_geometry(world.bodies[0].hulls[0], {touching[0].position, 0.0},
                               world.bodies[1].hulls[0], {Vec2::Zero(), 0.0}, 1e-9);
  REQUIRE(geometry.points.size() == 1);
  const oracle::Feature feature = geometry.points[0].feature;
  REQUIRE(feature.kind == oracle::Feature::Kind::VertexVertex);
  const oracle::EventWatch pairs(world, 1e-9, 1e-9);
  REQUIRE(pairs.pairs().size() == 1);
  const oracle::ActiveContact contact =
      oracle::make_active_contact(world, pairs.pairs()[0], 0, feature);
  REQUIRE(contact.first == 0);

  // Touching as armed: both corners hold the normal 45° inside their cones, sin 45° from the
  // nearer side (the end's cone is a half-plane: its sides are the axis's two normals).
  const CornerRoots start = corner_roots(world, contact, touching, touching);
  CHECK(start.second == Catch::Detail::Approx(std::sqrt(0.5)).epsilon(1e-12));
  CHECK(start.first == Catch::Detail::Approx(std::sqrt(0.5)).epsilon(1e-12));

  // The capsule turned 60° about its end: the end and n stay, the box's corner still holds n, but
  // −n is now 15° behind the end's half-plane (sin(−15°)): the capsule's side, not its end,
  // faces the corner, and that must be an event.
  const std::vector<oracle::Motion> turned = {capsule_at(end, kPi / 3), touching[1]};
  const CornerRoots after = corner_roots(world, contact, touching, turned);
  CHECK(after.second == Catch::Detail::Approx(std::sqrt(0.5)).epsilon(1e-12));
  CHECK(after.first == Catch::Detail::Approx(-std::sin(kPi / 12)).epsilon(1e-12));
}

}  // namespace test_oracle_event_watch
}  // namespace
