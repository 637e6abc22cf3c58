// Contacts stored in the order the solver visits them (Settings::stored_in_order_contacts) give
// the same result to the bit as contacts left in their own order: scenes/rain1000.json, whose
// discs land on others at rest (speculative contacts) in small islands (solved directly) and a
// pile of one-point contacts, stepped both ways with sleeping off and on, and with its pile cut
// into parts (whose order, unlike the levels', is not the contacts' own order at the cuts, so
// that every visit in their own order is checked), every body's state and every contact point
// compared at every step.

#include <algorithm>
#include <bit>
#include <catch2/catch.hpp>
#include <climits>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "engine/scene/scene_space.hpp"
#include "gamephysics/gamephysics.hpp"
#include "scene/scene.hpp"

namespace {
namespace test_stored_order {

constexpr int kSteps = 600;

// rain1000 with its pile cut into 8 parts when it holds more than `part_contacts` contacts (0:
// never cut, as its ~2500 contacts are not by the default 4096).
std::unique_ptr<gp::Space> rain(bool sleep, int part_contacts, int stored_in_order_contacts) {
  gp::Scene scene = gp::load_scene(GP_SOURCE_DIR "/scenes/rain1000.json");
  scene.settings.sleep = sleep;
  scene.settings.island_part_contacts = part_contacts;
  scene.settings.island_parts = 8;
  scene.settings.stored_in_order_contacts = stored_in_order_contacts;
  return gp::build_space(scene);
}

// Every body's state and every contact point's bodies and impulses, as bits.
std::vector<std::uint64_t> bits_of(const gp::Space& space) {
  std::vector<std::uint64_t> out;
  const auto add = [&](double x) { out.push_back(std::bit_cast<std::uint64_t>(x)); };
  for (gp::BodyId b = 0; b < space.body_count(); ++b) {
    const gp::BodyState s = space.state(b);
    for (const double x : {s.position.x(), s.position.y(), s.angle, s.velocity.x(), s.velocity.y(),
                           s.angular_velocity}) {
      add(x);
    }
  }
  for (const gp::ContactPointReport& p : space.contact_points()) {
    out.push_back(std::uint64_t{p.body_a} << 32 | p.body_b);
    add(p.normal_impulse);
    add(p.tangent_impulse);
  }
  return out;
}

TEST_CASE("Contacts stored in the solver's order step to the same bits as in their own",
          "[FR:Determine-Collision-Response-Over-Time]") {
  for (const auto& [sleep, part_contacts] :
       {std::pair{false, 0}, std::pair{true, 0}, std::pair{false, 512}}) {
    INFO("sleeping " << sleep << ", parts of " << part_contacts << " contacts");
    const auto own = rain(sleep, part_contacts, INT_MAX);
    const auto stored = rain(sleep, part_contacts, 0);
    std::size_t most_points = 0;
    for (int step = 0; step < kSteps; ++step) {
      own->step(1.0 / 60.0);
      stored->step(1.0 / 60.0);
      const std::vector<std::uint64_t> a = bits_of(*own);
      const std::vector<std::uint64_t> b = bits_of(*stored);
      const auto differ = std::mismatch(a.begin(), a.end(), b.begin(), b.end());
      INFO("step " << step << ": first differing entry " << differ.first - a.begin() << " of "
                   << a.size() << " (6 per body, then 3 per contact point)");
      REQUIRE(a == b);
      most_points = std::max(most_points, own->contact_points().size());
    }
    // The discs piled up: the comparison is of steps full of contacts.
    CHECK(most_points > 1000);
  }
}

}  // namespace test_stored_order
}  // namespace
