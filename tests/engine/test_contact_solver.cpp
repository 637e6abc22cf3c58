// The contact solver's passes and the position passes' rotations, against hand computations.

#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "engine/collision/collision_detection.hpp"
#include "engine/geometry/transform.hpp"
#include "engine/solver/contact_batches.hpp"
#include "engine/solver/position_passes.hpp"
#include "engine/solver/velocity_passes.hpp"

namespace {
namespace test_contact_solver {

constexpr double kGravity = 9.81;
constexpr double kStep = 1.0 / 60.0;

// A unit box of 1 kg (body 1) resting on static ground (body 0) at its two bottom corners, the
// step's gravity already in its velocity.
struct RestingBox {
  gp::BodyInertia inertia{{0.0, 1.0}, {0.0, 6.0}};  // a unit box: I = m (w² + h²) / 12 = 1/6
  gp::MotionState state;
  gp::BodyShapes shapes;
  gp::ContactSet contacts;

  RestingBox() {
    shapes.add(0, gp::Shape::segment({-5.0, 0.0}, {5.0, 0.0}), 0.0, 0.6, false);
    shapes.add(1, gp::Shape::box(1.0, 1.0), 0.0, 0.6, true);
    state.resize(2);
    state.position[1] = {0.0, 0.5};
    state.velocity[1] = {0.0, -kGravity * kStep};
    gp::Contact& c = contacts.append(2);
    c.shape_a = 1;
    c.body_a = 1;
    c.body_b = 0;
    c.normal = {0.0, 1.0};
    c.friction = 0.6;
    for (int k = 0; k < 2; ++k) {
      gp::ContactPointState& p = contacts.points(c)[k];
      const gp::Vec2 arm_a{k == 0 ? -0.5 : 0.5, -0.5};
      gp::set_arms(p, c.normal, arm_a, arm_a + gp::Vec2{0.0, 0.5});
    }
    gp::MotionState before = state;
    before.velocity[1] = gp::Vec2::Zero();
    gp::prepare_contacts(contacts, shapes, inertia, before, kStep, gp::Settings{});
  }
};

TEST_CASE("A box on the ground is stopped in one pass, each corner carrying half its weight",
          "[via:GD:impulse]") {
  RestingBox box;
  const int passes = gp::solve_velocities(box.contacts, box.inertia, 10, 1e-5, box.state);
  // The block solver meets both corners at once; the second pass finds nothing left to do.
  CHECK(passes == 2);
  CHECK(std::abs(box.state.velocity[1].y()) < 1e-15);
  CHECK(std::abs(box.state.angular_velocity[1]) < 1e-15);
  for (const auto& p : box.contacts.points(box.contacts[0])) {
    CHECK(p.normal_impulse == Approx(0.5 * kGravity * kStep).epsilon(1e-14));
    CHECK(p.tangent_impulse == 0.0);
  }
}

TEST_CASE("Warm-started with last step's impulses, a resting box needs a single pass",
          "[via:GD:impulse]") {
  RestingBox box;
  for (auto& p : box.contacts.points(box.contacts[0])) p.normal_impulse = 0.5 * kGravity * kStep;
  gp::warm_start(box.contacts, box.inertia, box.state);
  CHECK(gp::solve_velocities(box.contacts, box.inertia, 10, 1e-5, box.state) == 1);
  // Without the tolerance, the passes go on while anything at all changes.
  RestingBox cold;
  CHECK(gp::solve_velocities(cold.contacts, cold.inertia, 10, 0.0, cold.state) <= 3);
}

TEST_CASE("Prepared and warm-started in one pass, a resting box gets its masses and stops",
          "[via:GD:impulse]") {
  RestingBox box;
  gp::ContactPointState* points = box.contacts.points(box.contacts[0]).data();
  for (int k = 0; k < 2; ++k) {
    points[k].normal_mass = points[k].tangent_mass = 0.0;
    points[k].normal_impulse = 0.5 * kGravity * kStep;
  }
  // A block is left by the narrowphase as the last contact in its room had it: all of it is
  // written anew.
  const double nan = std::nan("");
  box.contacts.block(box.contacts[0]) = {nan, nan, nan, nan, nan, nan};
  gp::ContactBatches batches;
  batches.build(box.contacts, {}, box.inertia, box.state.position, {});
  gp::MotionState before = box.state;
  before.velocity[1] = gp::Vec2::Zero();
  gp::prepare_and_warm_start(batches, box.contacts,
                             {box.shapes, box.inertia, before, kStep, gp::Settings{}}, box.state);
  // Each corner's arm crosses the normal at ±0.5 m: 1 / (1/m + 0.5² / I) = 1 / 2.5 kg, and the
  // tangent at 0.5 m.
  for (int k = 0; k < 2; ++k) {
    CHECK(points[k].normal_mass == Approx(0.4).epsilon(1e-14));
    CHECK(points[k].tangent_mass == Approx(0.4).epsilon(1e-14));
  }
  // K: 1/m + (r₁ × n)(r₂ × n)/I = 1 − 0.25 · 6 = −0.5 kg⁻¹ off the diagonal, 2.5 on it; det 6.
  const gp::NormalBlock& k = box.contacts.block(box.contacts[0]);
  CHECK(k.k11 == Approx(2.5).epsilon(1e-14));
  CHECK(k.k22 == Approx(2.5).epsilon(1e-14));
  CHECK(k.k12 == Approx(-0.5).epsilon(1e-14));
  CHECK(k.inverse11 == Approx(2.5 / 6.0).epsilon(1e-14));
  CHECK(k.inverse12 == Approx(0.5 / 6.0).epsilon(1e-14));
  CHECK(k.inverse22 == Approx(2.5 / 6.0).epsilon(1e-14));
  // The two half weights carried over cancel the step's gravity, g h, of the 1 kg box.
  CHECK(std::abs(box.state.velocity[1].y()) < 1e-15);
  CHECK(std::abs(box.state.angular_velocity[1]) < 1e-15);
  CHECK(before.velocity[1].y() == 0.0);
}

TEST_CASE("Bodies moved by their velocity changes move as their contacts' impulses move them",
          "[via:DD:impulseV][via:DD:torque]") {
  RestingBox box;
  // A third body, free and touching nothing, which must not be written at all.
  box.inertia.inverse_mass.push_back(1.0);
  box.inertia.inverse_moment.push_back(6.0);
  box.state.resize(3);
  box.state.position[2] = {-0.0, 3.0};
  box.state.angle[2] = 1.0;
  box.state.velocity[2] = {1.0, 2.0};
  box.state.angle[1] = 0.5;
  gp::ContactPointState* points = box.contacts.points(box.contacts[0]).data();
  points[0].normal_impulse = 0.3;
  points[1].normal_impulse = 0.2;
  points[0].tangent_impulse = 0.05;
  points[1].tangent_impulse = -0.02;
  gp::BodyVelocities before;
  before.take(box.state, {});
  gp::warm_start(box.contacts, box.inertia, box.state);
  gp::MotionState by_contacts = box.state;
  gp::move_by_contact_impulses(box.contacts, box.inertia, kStep, by_contacts);
  gp::move_by_velocity_changes(before, kStep, box.state);
  // By hand: the normal impulses 0.5 N·s lift the 1 kg box by 0.5 h; the tangent's, 0.03 N·s
  // along (−1, 0), move it by −0.03 h; their moments about the centre, −0.5 · 0.3 + 0.5 · 0.2
  // (normal) and −0.5 · 0.03 (tangent), turn it by 6 · (−0.065) h.
  CHECK(box.state.position[1].x() == Approx(-0.03 * kStep).epsilon(1e-13));
  CHECK(box.state.position[1].y() == Approx(0.5 + 0.5 * kStep).epsilon(1e-15));
  CHECK(box.state.angle[1] == Approx(0.5 - 6.0 * 0.065 * kStep).epsilon(1e-15));
  for (int b : {1, 2}) {
    CHECK(box.state.position[b].x() == Approx(by_contacts.position[b].x()).margin(1e-16));
    CHECK(box.state.position[b].y() == Approx(by_contacts.position[b].y()).epsilon(1e-15));
    CHECK(box.state.angle[b] == Approx(by_contacts.angle[b]).epsilon(1e-15));
  }
  CHECK(std::signbit(box.state.position[2].x()));
  CHECK(box.state.angle[2] == 1.0);
  CHECK(box.state.position[0] == gp::Vec2::Zero());
}

TEST_CASE("A rotation turned by its series agrees with one built from the new angle",
          "[via:DD:angDisp]") {
  const gp::Rotation rotation(2.5);
  std::vector<double> turns{1e-3, -1e-3, 3e-7, 0.0, 1.0001e-3, -0.1, 0.1};
  std::mt19937 random(3);
  std::uniform_real_distribution<double> any_turn(-gp::Rotation::kLargestSeriesTurn,
                                                  gp::Rotation::kLargestSeriesTurn);
  for (int i = 0; i < 1000; ++i) turns.push_back(any_turn(random));
  for (const double turn : turns) {
    const gp::Rotation turned = rotation.turned(turn);
    const gp::Rotation exact(2.5 + turn);
    for (const gp::Vec2& v : {gp::Vec2{1.0, 0.0}, gp::Vec2{0.0, 1.0}, gp::Vec2{-0.3, 0.7}}) {
      INFO("turn " << turn);
      CHECK((turned.rotate(v) - exact.rotate(v)).norm() < 1e-13);
    }
  }
  // The series is not meant for larger turns: at 0.3 rad it errs by far more.
  CHECK((rotation.turned(0.3).rotate({1.0, 0.0}) - gp::Rotation(2.8).rotate({1.0, 0.0})).norm() >
        1e-11);
}

TEST_CASE("A point's arms come back from their cross products with the normal and tangent",
          "[via:DD:torque]") {
  for (double angle : {0.0, 0.7, 2.0, -2.9}) {
    gp::Contact c{};
    c.normal = {std::cos(angle), std::sin(angle)};
    gp::ContactPointState p;
    const gp::Vec2 arm_a{0.3, -1.7};
    const gp::Vec2 arm_b{-2.5, 0.4};
    gp::set_arms(p, c.normal, arm_a, arm_b);
    CHECK((gp::arm_a(c, p) - arm_a).norm() < 1e-15);
    CHECK((gp::arm_b(c, p) - arm_b).norm() < 1e-15);
    // The cross product with the normal is the torque of a unit normal impulse: r_x n_y − r_y n_x.
    CHECK(p.normal_arm_a == Approx(arm_a.x() * c.normal.y() - arm_a.y() * c.normal.x()));
  }
}

TEST_CASE("Dropping contacts from a set keeps each remaining contact with its own points and block",
          "[FR:Determine-Collisions]") {
  gp::ContactSet set;
  for (std::uint32_t i = 0; i < 5; ++i) {
    const int count = i % 2 == 0 ? 2 : 1;
    gp::Contact& c = set.append(count);
    c.shape_a = i;
    for (int k = 0; k < count; ++k) set.points(c)[k].depth = static_cast<float>(10 * i + k);
    if (count == 2) set.block(c) = gp::NormalBlock{.k11 = static_cast<double>(i)};
  }
  CHECK(set.point_count() == 8);
  set.erase_if([](const gp::Contact& c) { return c.shape_a == 0 || c.shape_a == 3; });
  REQUIRE(set.size() == 3);
  CHECK(set.point_count() == 5);
  for (const gp::Contact& c : set) {
    REQUIRE(set.points(c).size() == (c.shape_a % 2 == 0 ? 2u : 1u));
    for (std::size_t k = 0; k < set.points(c).size(); ++k) {
      CHECK(set.points(c)[k].depth == static_cast<float>(10 * c.shape_a + k));
    }
    if (c.count() == 2) CHECK(set.block(c).k11 == static_cast<double>(c.shape_a));
  }
}

// A body (1) of 1 kg and 1 kg·m² touching static ground (0) along the normal +y at one point
// overlapping by `depth`, its shape's deepest point found at `arm` from its centre of mass; the
// body then turned by `turn` about its centre of mass and lowered by `drop` [m] before the
// position pass (slop 0). Returns how far one position pass lifts it [m].
double lift_after_motion(const gp::Shape& shape, const gp::Vec2& arm, double depth, double turn,
                         double drop) {
  gp::BodyShapes shapes;
  shapes.add(0, gp::Shape::segment({-5.0, 0.0}, {5.0, 0.0}), 0.0, 0.0, false);
  shapes.add(1, shape, 0.0, 0.0, true);
  const gp::BodyInertia inertia{{0.0, 1.0}, {0.0, 1.0}};
  gp::MotionState s;
  s.resize(2);
  s.position[1] = {0.0, -arm.y() - depth};  // the deepest point `depth` under the ground
  const gp::MotionState detected = s;
  gp::ContactManifold m;
  m.normal = {0.0, 1.0};
  m.count = 1;
  // The contact point is midway between the two deepest points.
  m.points[0].position = s.position[1] + arm + gp::Vec2{0.0, 0.5 * depth};
  m.points[0].depth = depth;
  gp::ContactSet contacts;
  gp::append_contact({1, 0}, shapes, m, s, contacts);
  contacts.points(contacts[0])[0].normal_mass = 1.0;
  s.angle[1] = turn;
  s.position[1].y() -= drop;
  gp::PositionCorrection passes;
  passes.correct(contacts, {shapes, inertia, detected}, {1, 0.0}, s);
  return s.position[1].y() + drop + arm.y() + depth;
}

double lift_after_turn(const gp::Shape& shape, const gp::Vec2& arm, double depth, double turn) {
  return lift_after_motion(shape, arm, depth, turn, 0.0);
}

TEST_CASE("A position pass measures the overlap at the deepest points as their bodies turned",
          "[via:DD:angDisp]") {
  constexpr double kDepth = 1.0 / 64;  // m, exact as the float a contact point keeps
  constexpr double kTurn = 0.3;
  // A box's corner at (−0.5, −0.5) turns with the box: turned by 0.3 rad it is
  // 0.5 (cos 0.3 + sin 0.3) − 0.5 = 0.125 m lower. A pass lifts by a fifth of the overlap.
  const gp::Vec2 corner{-0.5, -0.5};
  const double corner_drop = -(std::sin(kTurn) * corner.x() + std::cos(kTurn) * corner.y()) - 0.5;
  CHECK(lift_after_turn(gp::Shape::box(1.0, 1.0), corner, kDepth, kTurn) ==
        Approx(0.2 * (kDepth + corner_drop)).epsilon(1e-12));
  // A disc on its centre of mass: its lowest point is its lowest point whichever way it turns.
  CHECK(lift_after_turn(gp::Shape::circle(0.5), {0.0, -0.5}, kDepth, kTurn) ==
        Approx(0.2 * kDepth).epsilon(1e-12));
  // A disc of radius 0.5 centred 1 m to the right of the centre of mass: turned by −0.3 rad, its
  // centre drops by sin 0.3 m, and so does its lowest point.
  CHECK(lift_after_turn(gp::Shape::circle(0.5, {1.0, 0.0}), {1.0, -0.5}, kDepth, -kTurn) ==
        Approx(0.2 * (kDepth + std::sin(kTurn))).epsilon(1e-12));
}

TEST_CASE("A position pass corrects a point apart at detection that its body's motion brought in",
          "[via:DD:angDisp]") {
  // The passes pass over a point whose overlap cannot have grown past the slop since detection,
  // by how far its bodies moved and turned; these points were 1/64 m apart, and then their
  // bodies turned or sank further than that.
  constexpr double kGap = 1.0 / 64;  // m, exact as the float a contact point keeps
  const gp::Vec2 corner{-0.5, -0.5};
  const gp::Shape box = gp::Shape::box(1.0, 1.0);
  // Turned by 0.3 rad, the corner is 0.5 (cos 0.3 + sin 0.3) − 0.5 = 0.125 m lower.
  constexpr double kTurn = 0.3;
  const double corner_drop = -(std::sin(kTurn) * corner.x() + std::cos(kTurn) * corner.y()) - 0.5;
  CHECK(lift_after_motion(box, corner, -kGap, kTurn, 0.0) ==
        Approx(0.2 * (corner_drop - kGap)).epsilon(1e-12));
  // Lowered by 4/64 m, the corner overlaps by 3/64 m; lowered by 1/128 m, it is still apart.
  CHECK(lift_after_motion(box, corner, -kGap, 0.0, 4 * kGap) ==
        Approx(0.2 * 3 * kGap).epsilon(1e-12));
  CHECK(lift_after_motion(box, corner, -kGap, 0.0, kGap / 2) == 0.0);
  // A disc on its centre of mass lowered by 4/64 m: the same 3/64 m, turned or not.
  CHECK(lift_after_motion(gp::Shape::circle(0.5), {0.0, -0.5}, -kGap, kTurn, 4 * kGap) ==
        Approx(0.2 * 3 * kGap).epsilon(1e-12));
}

}  // namespace test_contact_solver
}  // namespace
