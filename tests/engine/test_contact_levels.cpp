// The velocity and position passes over an island of one-point contacts, taken by levels (and,
// where the CPU has AVX2, a level's contacts four at a time): the same bits as the passes one
// contact after the other in the contacts' order, on one thread and on two, with the contacts
// left in their own order or stored in the passes'.

#include <algorithm>
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include <tbb/task_arena.h>

#include "engine/collision/body_shapes.hpp"
#include "engine/solver/contact_batches.hpp"
#include "engine/solver/position_passes.hpp"
#include "engine/solver/velocity_passes.hpp"

namespace {
namespace test_contact_levels {

constexpr int kColumns = 7;
constexpr int kRows = 6;
constexpr std::size_t kNever = std::numeric_limits<std::size_t>::max();

// Discs in a grid of kColumns × kRows (body 1 + column + kColumns · row), the bottom row on the
// static ground (body 0), each touching its neighbours to the right, above and above-right, the
// contacts in a random order. Normals, arms, masses, targets, velocities and warm starts random.
struct DiscGrid {
  std::mt19937_64 random;
  gp::BodyInertia inertia;
  gp::MotionState state;
  gp::MotionState detected;
  gp::BodyShapes shapes;
  gp::ContactSet contacts;
  std::vector<gp::Vec2> positions;

  explicit DiscGrid(std::uint64_t seed) : random(seed) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> positive(0.2, 3.0);
    const std::size_t bodies = 1 + kColumns * kRows;
    inertia.inverse_mass.assign(bodies, 0.0);
    inertia.inverse_moment.assign(bodies, 0.0);
    state.resize(bodies);
    positions.assign(bodies, gp::Vec2::Zero());
    const auto body = [](int column, int row) {
      return static_cast<gp::BodyId>(1 + column + kColumns * row);
    };
    std::vector<std::pair<gp::BodyId, gp::BodyId>> pairs;
    for (int row = 0; row < kRows; ++row) {
      for (int column = 0; column < kColumns; ++column) {
        const gp::BodyId b = body(column, row);
        inertia.inverse_mass[b] = positive(random);
        inertia.inverse_moment[b] = positive(random);
        state.velocity[b] = {unit(random), unit(random)};
        state.angular_velocity[b] = unit(random);
        positions[b] = {column, row};
        state.position[b] = {0.95 * column, 0.95 * row + 0.5};
        if (row == 0) pairs.emplace_back(b, 0);
        if (column + 1 < kColumns) pairs.emplace_back(body(column + 1, row), b);
        if (row + 1 < kRows) pairs.emplace_back(body(column, row + 1), b);
        if (row + 1 < kRows && column + 1 < kColumns)
          pairs.emplace_back(body(column + 1, row + 1), b);
      }
    }
    for (std::size_t b = 0; b < bodies; ++b) {
      shapes.add(static_cast<gp::BodyId>(b), gp::Shape::circle(0.5), 0.0, 0.5, b > 0);
    }
    std::shuffle(pairs.begin(), pairs.end(), random);
    for (const auto& [a, b] : pairs) {
      gp::Contact& c = contacts.append(1);
      c.body_a = c.shape_a = a;
      c.body_b = c.shape_b = b;
      const double angle = 3.0 * unit(random);
      c.normal = {std::cos(angle), std::sin(angle)};
      c.friction = contacts.size() % 5 == 0 ? 0.0 : positive(random) / 3.0;
      gp::ContactPointState& p = contacts.points(c)[0];
      gp::set_arms(p, c.normal, {unit(random), unit(random)}, {unit(random), unit(random)});
      // 1 / (1/m_A + 1/m_B + (r_A × d)²/I_A + (r_B × d)²/I_B), by hand.
      const auto effective = [&](double arm_a, double arm_b) {
        return 1.0 / (inertia.inverse_mass[a] + inertia.inverse_mass[b] +
                      arm_a * arm_a * inertia.inverse_moment[a] +
                      arm_b * arm_b * inertia.inverse_moment[b]);
      };
      p.normal_mass = effective(p.normal_arm_a, p.normal_arm_b);
      p.tangent_mass = effective(p.tangent_arm_a, p.tangent_arm_b);
      p.target_normal_velocity = 0.1 * unit(random);
      p.normal_impulse = std::abs(unit(random));
      p.tangent_impulse = c.friction * p.normal_impulse * unit(random);
      // For the position passes: discs about their centres, overlapping by 5 cm but the ground's
      // (body 0, at the origin), by up to 3 cm. Each arm along the normal reaches the point
      // midway between the centres, as the narrowphase's do the contact point, so that at
      // detection the deepest points lie −depth apart.
      p.anchor_a = p.anchor_b = gp::AnchorKind::kCentredDisc;
      const gp::Vec2 midway = 0.5 * (state.position[a] + state.position[b]);
      p.tangent_arm_a = (midway - state.position[a]).dot(c.normal);
      p.tangent_arm_b = (midway - state.position[b]).dot(c.normal);
      p.depth = static_cast<float>(b == 0 ? 0.03 * std::abs(unit(random)) : 0.05);
    }
    // Since detection the discs moved by up to 1 mm.
    detected = state;
    for (std::size_t b = 1; b < bodies; ++b) {
      state.position[b] += gp::Vec2{1e-3 * unit(random), 1e-3 * unit(random)};
    }
  }
};

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

void check_same_bits(const DiscGrid& levels, const DiscGrid& in_order) {
  for (std::size_t b = 0; b < levels.state.velocity.size(); ++b) {
    INFO("body " << b);
    CHECK(bits(levels.state.velocity[b].x()) == bits(in_order.state.velocity[b].x()));
    CHECK(bits(levels.state.velocity[b].y()) == bits(in_order.state.velocity[b].y()));
    CHECK(bits(levels.state.angular_velocity[b]) == bits(in_order.state.angular_velocity[b]));
  }
  for (std::size_t i = 0; i < levels.contacts.size(); ++i) {
    const gp::ContactPointState& p = levels.contacts.points(levels.contacts[i])[0];
    const gp::ContactPointState& q = in_order.contacts.points(in_order.contacts[i])[0];
    INFO("contact " << i);
    CHECK(bits(p.normal_impulse) == bits(q.normal_impulse));
    CHECK(bits(p.tangent_impulse) == bits(q.tangent_impulse));
  }
}

// The contacts stored where the passes visit them, as ContactBatches::store_in_order does for a
// large set, or left in their own order.
enum class Storage { kOwnOrder, kSolveOrder };

// `pass(batches)` on `grid`'s contacts by levels, stored as `storage` says; they are back in their
// own order after.
template <typename Pass>
void by_levels(DiscGrid& grid, Storage storage, const Pass& pass) {
  gp::ContactBatches batches;
  batches.build(grid.contacts, {}, grid.inertia, grid.positions,
                {4096, 0, storage == Storage::kSolveOrder ? 0 : kNever});
  batches.store_in_order(grid.contacts);
  if (storage == Storage::kSolveOrder) {
    // Moved: the levels put the contacts out of their own (shuffled) order.
    REQUIRE(batches.stored_at().size() == grid.contacts.size());
    std::size_t moved = 0;
    for (std::uint32_t i = 0; i < grid.contacts.size(); ++i) moved += batches.stored_at()[i] != i;
    CHECK(moved > grid.contacts.size() / 2);
  } else {
    CHECK(batches.stored_at().empty());
  }
  pass(batches);
  batches.restore_order(grid.contacts);
}

TEST_CASE("Velocity passes by levels give the same bits as in the contacts' order",
          "[via:GD:impulse][via:DD:impulseV]") {
  constexpr int kPasses = 6;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    for (const int threads : {1, 2}) {
      for (const Storage storage : {Storage::kOwnOrder, Storage::kSolveOrder}) {
        INFO("seed " << seed << ", " << threads << " threads, stored in solve order "
                     << (storage == Storage::kSolveOrder));
        DiscGrid in_order(seed);
        const int passes_in_order =
            gp::solve_velocities(in_order.contacts, in_order.inertia, kPasses, 0.0, in_order.state);
        DiscGrid levels(seed);
        int passes_levels = 0;
        by_levels(levels, storage, [&](const gp::ContactBatches& batches) {
          passes_levels = tbb::task_arena(threads).execute([&] {
            return gp::solve_velocities(batches, levels.contacts, levels.inertia, {kPasses, 0.0},
                                        levels.state);
          });
        });
        CHECK(passes_levels == passes_in_order);
        check_same_bits(levels, in_order);
      }
    }
  }
}

TEST_CASE("Position passes by levels give the same bits as in the contacts' order",
          "[via:DD:impulseV]") {
  constexpr gp::PositionLimits kLimits{4, 0.005};
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    for (const int threads : {1, 2}) {
      INFO("seed " << seed << ", " << threads << " threads");
      DiscGrid in_order(seed);
      gp::PositionCorrection one;
      one.correct(in_order.contacts, {in_order.shapes, in_order.inertia, in_order.detected},
                  kLimits, in_order.state);
      for (const Storage storage : {Storage::kOwnOrder, Storage::kSolveOrder}) {
        INFO("stored in solve order " << (storage == Storage::kSolveOrder));
        DiscGrid levels(seed);
        gp::PositionCorrection correction;
        const std::vector<gp::Vec2> before = levels.state.position;
        by_levels(levels, storage, [&](const gp::ContactBatches& batches) {
          tbb::task_arena(threads).execute([&] {
            correction.correct(batches, levels.contacts,
                               {levels.shapes, levels.inertia, levels.detected}, kLimits,
                               levels.state);
          });
        });
        for (std::size_t b = 0; b < levels.state.position.size(); ++b) {
          INFO("body " << b);
          CHECK(bits(levels.state.position[b].x()) == bits(in_order.state.position[b].x()));
          CHECK(bits(levels.state.position[b].y()) == bits(in_order.state.position[b].y()));
          CHECK(bits(levels.state.angle[b]) == bits(in_order.state.angle[b]));
        }
        // The passes moved the discs: the comparison is not of untouched states.
        CHECK(levels.state.position != before);
      }
    }
  }
}

}  // namespace test_contact_levels
}  // namespace
