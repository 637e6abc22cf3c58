// Position passes over contacts between centred discs four at a time: the same bits as the pass
// one at a time, and the separation each acting contact gains checked by hand.

#include <algorithm>
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "engine/collision/body_shapes.hpp"
#include "engine/solver/disc_position_lanes.hpp"
#include "engine/solver/position_passes.hpp"
#include "random_colour.hpp"

namespace {
namespace test_disc_position_lanes {

constexpr std::size_t kContacts = gp::test::kColourContacts;
constexpr double kSlop = 0.005;  // m

// The colour of random_colour.hpp, of contacts between discs about their centres of mass (the
// static body a disc too). Each A is placed against its B as the depth says; the motion since
// detection, depths and masses are random, with the cases the lanes must keep apart: a point
// passed over (1: within the slop, A unmoved), one moved apart past its room (6: no excess), one
// so deep its correction is capped (8), and a body at angle −0.0 (5), which a pass that moves it
// writes back as +0.0.
struct Discs : gp::test::RandomColour {
  gp::BodyShapes shapes;
  gp::MotionState detected;

  explicit Discs(std::uint64_t seed) : RandomColour(seed) {
    const std::size_t bodies = gp::test::kColourBodies;
    for (std::size_t b = 0; b < bodies; ++b) {
      shapes.add(static_cast<gp::BodyId>(b), gp::Shape::circle(0.5), 0.0, 0.5, b > 0);
      state.position[b] = {10.0 * unit(random), 10.0 * unit(random)};
      state.angle[b] = 3.0 + 3.0 * unit(random);
    }
    for (std::uint32_t i = 0; i < kContacts; ++i) {
      gp::Contact& c = set.append(1);
      c.body_a = c.shape_a = gp::test::colour_body_a(i);
      c.body_b = c.shape_b = gp::test::colour_body_b(i);
      const double angle = 3.0 * unit(random);
      c.normal = {std::cos(angle), std::sin(angle)};
      gp::ContactPointState& p = set.points(c)[0];
      p.anchor_a = p.anchor_b = gp::AnchorKind::kCentredDisc;
      p.tangent_arm_a = -0.5 + 0.01 * unit(random);  // the radius along −n, to the contact point
      p.tangent_arm_b = 0.5 + 0.01 * unit(random);
      p.normal_mass = positive(random);
      const double depth = i == 1   ? 0.5 * kSlop
                           : i == 2 ? 0.02
                           : i == 6 ? -0.1
                           : i == 8 ? 2.0
                                    : 0.03 * unit(random);
      p.depth = static_cast<float>(depth);
      // A placed so that at detection its deepest point and B's are apart by −depth.
      state.position[c.body_a] =
          state.position[c.body_b] + (p.tangent_arm_b - p.tangent_arm_a) * c.normal;
      indices.push_back(i);
    }
    detected = state;
    // Since detection the bodies moved by up to 1 mm and turned (which turns no centred disc's
    // deepest point); body 3 (contact 1's A) not at all, body 13 (contact 6's A) 0.2 m away.
    for (std::size_t b = 1; b < bodies; ++b) {
      if (b == 3) continue;
      state.position[b] += gp::Vec2{1e-3 * unit(random), 1e-3 * unit(random)};
      state.angle[b] += 0.1 * unit(random);
    }
    state.angle[5] = -0.0;
    state.position[13] += 0.2 * set[6].normal;
  }

  // The separation [m] of contact i's bodies' deepest points along its normal, by hand: each
  // deepest point is its contact point's arm plus or minus half the depth along the normal.
  double separation(std::uint32_t i) const {
    const gp::Contact& c = set[i];
    const gp::ContactPointState& p = set.points(c)[0];
    const double half = 0.5 * p.depth;
    return (state.position[c.body_a] - state.position[c.body_b]).dot(c.normal) +
           (p.tangent_arm_a - half) - (p.tangent_arm_b + half);
  }
};

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

TEST_CASE("Centred discs' position pass four at a time is the same to the bit as one at a time",
          "[via:DD:angDisp][via:DD:impulseV]") {
  if (!gp::four_lanes()) {
    WARN("no AVX2 on this CPU: the position passes take contacts one at a time");
    return;
  }
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Discs lanes(seed);
    Discs one(seed);
    const bool deep =
        gp::correct_centred_discs(lanes.set, lanes.indices, {lanes.inertia, kSlop}, lanes.state);
    gp::PositionCorrection passes;
    passes.correct(one.set, {one.shapes, one.inertia, one.detected}, {1, kSlop}, one.state);
    INFO("seed " << seed);
    for (std::size_t b = 0; b < lanes.state.position.size(); ++b) {
      CHECK(bits(lanes.state.position[b].x()) == bits(one.state.position[b].x()));
      CHECK(bits(lanes.state.position[b].y()) == bits(one.state.position[b].y()));
      CHECK(bits(lanes.state.angle[b]) == bits(one.state.angle[b]));
    }
    // Contact 8 overlaps by 2 m, far past two slops.
    CHECK(deep);
  }
}

TEST_CASE("Centred discs' position pass four at a time removes a fifth of each excess overlap",
          "[via:DD:impulseV]") {
  if (!gp::four_lanes()) {
    WARN("no AVX2 on this CPU: the position passes take contacts one at a time");
    return;
  }
  Discs discs(7);
  std::vector<double> before;
  for (const std::uint32_t i : discs.indices) before.push_back(discs.separation(i));
  const gp::Vec2 moved_before = discs.state.position[3];
  gp::correct_centred_discs(discs.set, discs.indices, {discs.inertia, kSlop}, discs.state);
  int corrected = 0;
  for (const std::uint32_t i : discs.indices) {
    const gp::Contact& c = discs.set[i];
    INFO("contact " << i << ", separation before " << before[i]);
    // Baumgarte's 0.2 of the excess overlap (at most 0.2 m, as for contact 8), times the
    // effective mass, moves A along n and B back over their masses: the gap opens by the sum.
    const double excess = std::clamp(0.2 * (before[i] + kSlop), -0.2, 0.0);
    const double opened =
        -excess * discs.set.points(c)[0].normal_mass *
        (discs.inertia.inverse_mass[c.body_a] + discs.inertia.inverse_mass[c.body_b]);
    // A point that overlapped by less than the slop at detection is passed over unless its
    // bodies moved farther than the room left: these barely moved.
    if (discs.set.points(c)[0].depth < kSlop) {
      CHECK(discs.separation(i) == before[i]);
      continue;
    }
    CHECK(discs.separation(i) == Approx(before[i] + opened).margin(1e-12));
    ++corrected;
  }
  CHECK(corrected >= 3);                               // contacts 2 and 8, and random ones
  CHECK(discs.state.position[3] == moved_before);      // contact 1's A, passed over
  CHECK(std::signbit(discs.state.angle[5]) == false);  // −0.0 moved, and written as +0.0
  CHECK(discs.state.position[0] == discs.detected.position[0]);  // static, shared, not moved
}

}  // namespace test_disc_position_lanes
}  // namespace
