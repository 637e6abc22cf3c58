// TrivialRoom keeps what was written through growing and shrinking, and its bytes are in the heap
// account, against entries and sizes worked out by hand.

#include <catch2/catch.hpp>
#include <cstddef>
#include <utility>

#include "engine/core.hpp"
#include "engine/trivial_room.hpp"
#include "heap_counter.hpp"

namespace {
namespace test_trivial_room {

struct Entry {
  gp::Vec2 place;
  int id;
};

TEST_CASE("a room keeps its first entries as it grows and shrinks", "[trivial_room]") {
  gp::TrivialRoom<Entry> room;
  CHECK(room.size() == 0);
  room.resize(3);
  for (int i = 0; i < 3; ++i) room[static_cast<std::size_t>(i)] = {gp::Vec2(i, -i), 10 + i};
  // Large enough to be mapped apart, which realloc remaps rather than copies.
  room.resize(1 << 16);
  REQUIRE(room.size() == 1 << 16);
  CHECK(room[2].place == gp::Vec2(2, -2));
  CHECK(room[2].id == 12);
  room[(1 << 16) - 1].id = 7;
  room.resize(2);
  CHECK(room[0].id == 10);
  CHECK(room[1].place == gp::Vec2(1, -1));
  const gp::TrivialRoom<Entry> copy = room;
  room[0].id = 99;
  CHECK(copy.size() == 2);
  CHECK(copy[0].id == 10);
  gp::TrivialRoom<Entry> moved = std::move(room);
  CHECK(moved[0].id == 99);
  CHECK(room.size() == 0);
}

TEST_CASE("the heap account holds a room's bytes until it is freed", "[trivial_room]") {
  // Read before any assertion, which might allocate for its report.
  const std::size_t before = gp::test::heap_in_use();
  const long allocations_before = gp::test::allocations();
  std::size_t grown = 0;
  std::size_t shrunk = 0;
  long allocations = 0;
  {
    gp::TrivialRoom<double> room;
    room.resize(1000);
    grown = gp::test::heap_in_use() - before;
    room.resize(250);
    shrunk = gp::test::heap_in_use() - before;
    allocations = gp::test::allocations() - allocations_before;
  }
  const std::size_t after = gp::test::heap_in_use();
  CHECK(grown == 8000);
  CHECK(shrunk == 2000);
  CHECK(allocations == 2);
  CHECK(after == before);
}

}  // namespace test_trivial_room
}  // namespace
