// Where ContactSet puts contacts: reserve hands out slots in order, as appending one by one would,
// a contact placed in reused room starts from zero, and reorder moves contacts as a permutation
// says, against layouts worked out by hand.

#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/capacity.hpp"
#include "engine/solver/contact_set.hpp"
#include "heap_counter.hpp"

namespace {
namespace test_contact_set {

TEST_CASE("reserve hands out the slots that appending one by one gives", "[contact_set]") {
  gp::ContactSet set;
  set.append(1);
  // After a one-point contact, a run of contacts of 2 and 1 points, an empty run, and a run of
  // one of 2 points: contacts 1, 2, 3 with points from 1, 3 and 4, blocks 0 and 1.
  std::array<gp::ContactCursor, 3> runs{};
  runs[0].take(2);
  runs[0].take(1);
  runs[2].take(2);
  CHECK(runs[0].contact == 2);
  CHECK(runs[0].point == 3);
  CHECK(runs[0].block == 1);
  set.reserve(runs);
  CHECK(set.size() == 4);
  CHECK(set.point_count() == 6);
  std::array<gp::ContactSlot, 3> slots{runs[0].take(2), runs[0].take(1), runs[2].take(2)};
  CHECK(slots[0].contact == 1);
  CHECK(slots[0].first_point == 1);
  CHECK(slots[0].block == 0);
  CHECK(slots[1].contact == 2);
  CHECK(slots[1].first_point == 3);
  CHECK(slots[1].block == gp::Contact::kNoBlock);
  // The empty run starts where the next one does.
  CHECK(runs[1].contact == 3);
  CHECK(slots[2].contact == 3);
  CHECK(slots[2].first_point == 4);
  CHECK(slots[2].block == 1);
  // Placed out of order, as threads may: each contact knows its points.
  for (int i : {2, 0, 1}) set.place(slots[static_cast<std::size_t>(i)]);
  CHECK(set[1].count() == 2);
  CHECK(set[2].count() == 1);
  CHECK(set.points(set[3]).data() == set.points(set[1]).data() + 3);
}

TEST_CASE("a contact placed in room a cleared contact left starts from zero, but for its block",
          "[contact_set]") {
  gp::ContactSet set;
  gp::Contact& old = set.append(2);
  old.body_a = 7;
  old.friction = 0.5;
  set.points(old)[1].normal_impulse = 3.0;
  set.block(old) = {1.0, 2.0, 3.0, 4.0, 5.0, 6.0};
  set.clear();
  CHECK(set.empty());
  const gp::Contact& again = set.append(2);
  CHECK(again.body_a == 0);
  CHECK(again.friction == 0.0);
  CHECK(set.points(again)[1].normal_impulse == 0.0);
  // The block is the preparation's to write whole (test_contact_solver: "Prepared and ...").
  CHECK(set.block(again).k12 == 2.0);
}

TEST_CASE("erase_if keeps the others in order with their points", "[contact_set]") {
  gp::ContactSet set;
  for (int count : {2, 1, 2}) {
    gp::Contact& c = set.append(count);
    c.body_a = static_cast<gp::BodyId>(set.size());
    set.points(c)[0].normal_impulse = static_cast<double>(set.size());
    if (count == 2) set.block(c).k11 = static_cast<double>(set.size());
  }
  set.erase_if([](const gp::Contact& c) { return c.body_a == 2; });
  REQUIRE(set.size() == 2);
  CHECK(set.point_count() == 4);
  CHECK(set[1].body_a == 3);
  CHECK(set[1].first_point == 2);
  CHECK(set.points(set[1])[0].normal_impulse == 3.0);
  CHECK(set.block(set[1]).k11 == 3.0);
}

TEST_CASE("bounce velocities stay with their points and go with a clear", "[contact_set]") {
  gp::ContactSet set;
  for (int count : {2, 1, 2}) set.append(count);
  set.keep_bounce_velocities(true);
  for (std::size_t i = 0; i < set.size(); ++i) {
    std::span<double> bounces = set.bounce_velocities(set[i]);
    for (std::size_t k = 0; k < bounces.size(); ++k) bounces[k] = -10.0 * double(i) - double(k);
    set[i].body_a = static_cast<gp::BodyId>(i);
  }
  set.erase_if([](const gp::Contact& c) { return c.body_a == 1; });
  REQUIRE(set.size() == 2);
  CHECK(set.bounce_velocities(set[1])[0] == -20.0);
  CHECK(set.bounce_velocities(set[1])[1] == -21.0);
  // A contact placed after them starts without a bounce.
  const gp::Contact& added = set.append(1);
  CHECK(set.bounce_velocities(added)[0] == 0.0);
  set.clear();
  CHECK_FALSE(set.keeps_bounce_velocities());
}

TEST_CASE("reorder moves each one-point contact with its point and bounce, restore_order back",
          "[contact_set]") {
  gp::ContactSet set;
  constexpr std::size_t kContacts = 10;
  for (std::size_t i = 0; i < kContacts; ++i) set.append(1);
  CHECK(set.single_points());
  set.keep_bounce_velocities(true);
  for (std::size_t i = 0; i < kContacts; ++i) {
    set[i].body_a = static_cast<gp::BodyId>(100 + i);
    set.points(set[i])[0].normal_impulse = static_cast<double>(i);
    set.bounce_velocities(set[i])[0] = -static_cast<double>(i);
  }
  // Contact k goes to to[k]: the cycles (0 4 2), (1 3) and (5 8 7 6), and 9 stays.
  const std::array<std::uint32_t, kContacts> to{4, 3, 0, 1, 2, 8, 5, 6, 7, 9};
  std::vector<bool> moved;
  set.reorder(to, moved);
  for (std::size_t k = 0; k < kContacts; ++k) {
    INFO("contact " << k);
    const gp::Contact& c = set[to[k]];
    CHECK(c.body_a == 100 + k);
    CHECK(c.first_point == to[k]);
    CHECK(set.points(c)[0].normal_impulse == static_cast<double>(k));
    CHECK(set.bounce_velocities(c)[0] == -static_cast<double>(k));
  }
  set.restore_order(to, moved);
  for (std::size_t i = 0; i < kContacts; ++i) {
    INFO("index " << i);
    CHECK(set[i].body_a == 100 + i);
    CHECK(set[i].first_point == i);
    CHECK(set.points(set[i])[0].normal_impulse == static_cast<double>(i));
    CHECK(set.bounce_velocities(set[i])[0] == -static_cast<double>(i));
  }
  set.append(2);
  CHECK_FALSE(set.single_points());
}

TEST_CASE("a pile's contacts appended from none take a few allocations and keep an eighth more",
          "[contact_set]") {
  constexpr std::size_t kContacts = 10000;
  const std::size_t heap_before = gp::test::heap_in_use();
  const long allocations_before = gp::test::allocations();
  gp::ContactSet set;
  for (std::size_t i = 0; i < kContacts; ++i) set.append(2);
  // Doubling: about log2(10,000) = 14 allocations for each of the contacts, points and blocks;
  // growing by an eighth each time would take about 70 each.
  CHECK(gp::test::allocations() - allocations_before <= 3 * 16);
  set.fit_room();
  const std::size_t per_contact =
      sizeof(gp::Contact) + 2 * sizeof(gp::ContactPointState) + sizeof(gp::NormalBlock);
  // Doubled to 16,384 it would hold 1.6 times what it needs; the allocator maps each of the three
  // arrays in whole pages.
  CHECK(gp::test::heap_in_use() - heap_before <=
        gp::grown_room(kContacts) * per_contact + 3 * 4096);
  CHECK(set.size() == kContacts);
  CHECK(set.points(set[kContacts - 1]).data() == set.points(set[0]).data() + 2 * kContacts - 2);
}

}  // namespace test_contact_set
}  // namespace
