// Memory per body: the heap a space holds once a rain of discs has settled into a heap, per disc,
// from two sizes of the same scene so that what does not grow with the bodies cancels. The issue
// asks for at most 1 KiB per body; the engine holds 939 B. The contact constraints (about two per
// disc, 136 bytes each with one point) are the largest part, about 0.4 KiB with their warm starts.
// A pile of boxes asleep holds no room for its contacts, which an awake one needs.
#include <catch2/catch.hpp>
#include <string>

#include "box_pyramid.hpp"
#include "gamephysics/gamephysics.hpp"
#include "heap_counter.hpp"

using gp::Vec2;

namespace {
namespace test_memory_per_body {

gp::BodyDef box_of_walls() {
  gp::BodyDef def;
  def.name = "box";
  def.type = gp::BodyType::Static;
  for (const auto& [a, b] : {std::pair(Vec2(-40.0, 0.0), Vec2(40.0, 0.0)),
                             std::pair(Vec2(-40.0, 0.0), Vec2(-40.0, 60.0)),
                             std::pair(Vec2(40.0, 0.0), Vec2(40.0, 60.0))}) {
    def.shapes.push_back({gp::Shape::segment(a, b), 0.0, 0.6, 1.0});
  }
  return def;
}

// rain1000's layout: rows of 40 discs 1.5 m apart, every other row shifted by half of that.
gp::BodyDef disc(int i) {
  gp::BodyDef def;
  // The letter inserted, not "d" + …, which GCC 12 flags falsely (-Wstringop-overflow).
  def.name = std::to_string(i).insert(0, 1, 'd');
  const int row = i / 40;
  def.position = {-29.25 + 1.5 * (i % 40) + (row % 2 == 1 ? 0.75 : 0.0), 5.0 + 1.5 * row};
  def.shapes.push_back({gp::Shape::circle(0.5), 0.0, 0.6, 1.0});
  return def;
}

// Heap held by a space of `discs` discs after they have fallen and come to rest [bytes].
std::size_t settled_heap(int discs) {
  const std::size_t before = gp::test::heap_in_use();
  gp::Settings settings;
  settings.gravity = {0.0, -9.81};
  gp::Space space(settings);
  space.add_body(box_of_walls());
  for (int i = 0; i < discs; ++i) space.add_body(disc(i));
  for (int k = 0; k < 360; ++k) space.step(1.0 / 60);
  return gp::test::heap_in_use() - before;
}

TEST_CASE("A settled heap of discs holds at most 1 KiB of heap per disc", "[FR:Simulation-Space]") {
  const double per_body = static_cast<double>(settled_heap(600) - settled_heap(200)) / 400.0;
  INFO("heap per body: " << per_body << " B");
  CHECK(per_body <= 1024.0);
}

// Heap held by a space of a pyramid of `rows` rows of unit boxes 5 cm apart, with sleep on or
// off, after two seconds: settled, and with sleep on asleep [bytes].
std::size_t pyramid_heap(int rows, bool sleep) {
  const std::size_t before = gp::test::heap_in_use();
  gp::Settings settings;
  settings.gravity = {0.0, -9.81};
  settings.sleep = sleep;
  gp::Space space(settings);
  gp::test::add_box_pyramid(space, rows, 1.05);
  for (int k = 0; k < 120; ++k) space.step(1.0 / 60);
  return gp::test::heap_in_use() - before;
}

TEST_CASE("A pile of boxes asleep holds no room for its contacts: under 1 KiB of heap a box",
          "[FR:Simulation-Space]") {
  // 210 boxes less 55: what does not grow with the boxes cancels.
  const auto per_box = [](bool sleep) {
    return static_cast<double>(pyramid_heap(20, sleep) - pyramid_heap(10, sleep)) / 155.0;
  };
  const double asleep = per_box(true);
  const double awake = per_box(false);
  INFO("heap per box asleep: " << asleep << " B, awake: " << awake << " B");
  CHECK(asleep <= 1024.0);
  // Awake, its contacts' room is more than half of what a box holds.
  CHECK(awake > 1.5 * asleep);
}

}  // namespace test_memory_per_body
}  // namespace
