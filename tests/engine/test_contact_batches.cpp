// The order of the contact passes (ContactBatches): every contact once, islands in the contacts'
// order, large islands in parts or by colour, against orders worked out by hand for chains of
// bodies.

#include <algorithm>
#include <atomic>
#include <catch2/catch.hpp>
#include <cstdint>
#include <limits>
#include <mutex>
#include <span>
#include <thread>
#include <vector>

#include <tbb/task_arena.h>

#include "engine/solver/contact_batches.hpp"

namespace {
namespace test_contact_batches {

// `bodies` unit bodies, body 0 static, body b at (b, 0), and one single-point contact per pair of
// `links`.
struct Graph {
  gp::BodyInertia inertia;
  gp::ContactSet contacts;
  std::vector<gp::Vec2> positions;

  Graph(std::size_t bodies, const std::vector<std::pair<gp::BodyId, gp::BodyId>>& links) {
    for (std::size_t b = 0; b < bodies; ++b) positions.emplace_back(static_cast<double>(b), 0.0);
    inertia.inverse_mass.assign(bodies, 1.0);
    inertia.inverse_moment.assign(bodies, 6.0);
    inertia.inverse_mass[0] = inertia.inverse_moment[0] = 0.0;
    for (const auto& [a, b] : links) {
      gp::Contact& c = contacts.append(1);
      c.body_a = c.shape_a = a;
      c.body_b = c.shape_b = b;
    }
  }
};

// A chain 1 - 2 - ... - n of movable bodies, each also resting on the static body 0, contact
// i + 1 joining bodies i + 1 and i + 2 after the ground contact of body 1.
Graph chain(std::size_t n) {
  std::vector<std::pair<gp::BodyId, gp::BodyId>> links{{1, 0}};
  for (gp::BodyId b = 1; b < n; ++b) links.emplace_back(b, b + 1);
  return Graph(n + 1, links);
}

// 0, 1, ..., n - 1: the contacts' own order.
std::vector<std::uint32_t> in_order(std::size_t n) {
  std::vector<std::uint32_t> order(n);
  for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
  return order;
}

// Islands of more contacts than this are coloured in these tests.
constexpr std::size_t kColouredAbove = 4096;
// Islands of more than 3 contacts cut into four parts.
constexpr gp::IslandSplitting kFourParts{.parted_above = 3, .parts = 4};

using Visit = gp::ContactBatches::Visit;

// The contact indices in the order one thread visits them as `visit` says, once `batches` is
// built for `g`, whose contacts' points were kept at the end of the last pass as `last_kept`.
std::vector<std::uint32_t> visits(gp::ContactBatches& batches, const Graph& g,
                                  gp::IslandSplitting splitting,
                                  const std::vector<gp::WarmStart>& last_kept = {},
                                  Visit visit = {}) {
  batches.build(g.contacts, last_kept, g.inertia, g.positions, splitting);
  std::vector<std::uint32_t> order;
  const auto visit_one = [&](std::uint32_t i) {
    order.push_back(i);
    return 0.0;
  };
  tbb::task_arena(1).execute([&] {
    batches.run(
        visit_one,
        [&](std::span<const std::uint32_t> independent) {
          for (const std::uint32_t i : independent) visit_one(i);
          return 0.0;
        },
        visit);
  });
  return order;
}

// The same, built afresh.
std::vector<std::uint32_t> visits(const Graph& g,
                                  gp::IslandSplitting splitting = {0, kColouredAbove},
                                  Visit visit = {}) {
  gp::ContactBatches batches;
  return visits(batches, g, splitting, {}, visit);
}

TEST_CASE("An island under the colouring threshold is visited in the contacts' own order") {
  const Graph g = chain(kColouredAbove);
  CHECK(visits(g) == in_order(g.contacts.size()));
}

TEST_CASE("With colouring off, a large island is visited in the contacts' own order") {
  const Graph g = chain(kColouredAbove + 10);
  CHECK(visits(g, {0, 0}) == in_order(g.contacts.size()));
}

TEST_CASE("Islands joined only through a static body are separate, each in its own order") {
  // Bodies 1..4 each on the ground, and 1 - 2 and 3 - 4 linked: islands {1, 2} and {3, 4}, each
  // island's contacts in their order, the island of the lower root first.
  const Graph g(5, {{3, 0}, {1, 0}, {3, 4}, {2, 1}, {4, 0}, {2, 0}});
  CHECK(visits(g) == std::vector<std::uint32_t>{1, 3, 5, 0, 2, 4});
}

TEST_CASE("Interleaved, each island's contacts are visited in two halves, taken by turns") {
  // The islands above, {1, 3, 5} and {0, 2, 4}: halves {1, 3} and {5}, {0, 2} and {4}; one
  // thread takes both islands at once, and each is interleaved on its own.
  const Graph g(5, {{3, 0}, {1, 0}, {3, 4}, {2, 1}, {4, 0}, {2, 0}});
  CHECK(visits(g, {0, kColouredAbove}, Visit{.interleaved = true}) ==
        std::vector<std::uint32_t>{1, 5, 3, 0, 4, 2});
  // A chain's six contacts, every two in a row sharing a body: none of the pairs visited in a
  // row does.
  CHECK(visits(chain(6), {0, kColouredAbove}, Visit{.interleaved = true}) ==
        std::vector<std::uint32_t>{0, 3, 1, 4, 2, 5});
}

// The runs of contacts a pass by levels hands over at once, each as a list, and the contacts it
// visits one at a time, each a list of one, in the order one thread visits them, the tasks not
// levelled in interleaved halves or in order.
std::vector<std::vector<std::uint32_t>> level_runs(const Graph& g, bool interleaved = true) {
  gp::ContactBatches batches;
  batches.build(g.contacts, {}, g.inertia, g.positions, {0, kColouredAbove});
  std::vector<std::vector<std::uint32_t>> runs;
  tbb::task_arena(1).execute([&] {
    batches.run(
        [&](std::uint32_t i) {
          runs.push_back({i});
          return 0.0;
        },
        [&](std::span<const std::uint32_t> independent) {
          runs.emplace_back(independent.begin(), independent.end());
          return 0.0;
        },
        Visit{.by_levels = true, .interleaved = interleaved});
  });
  return runs;
}

TEST_CASE("By levels, an island of one-point contacts is visited level after level") {
  // Three bodies in a row on the ground, contacts 0-2 theirs on the ground, 3 between bodies 1
  // and 2, 4 between 2 and 3: contacts 0, 1 and 2 share no body (level 1), 3 follows 0 and 1, and
  // 4 follows 3 (through body 2) and 2.
  const Graph row(4, {{1, 0}, {2, 0}, {3, 0}, {1, 2}, {2, 3}});
  using Runs = std::vector<std::vector<std::uint32_t>>;
  CHECK(level_runs(row) == Runs{{0, 1, 2}, {3}, {4}});
  // A chain: every contact follows the one before, a level each.
  CHECK(level_runs(chain(4)) == Runs{{0}, {1}, {2}, {3}});
  // A two-point contact in the island: visited one at a time instead, in interleaved halves or
  // in order.
  Graph mixed(4, {{1, 0}, {2, 0}, {3, 0}, {1, 2}});
  gp::Contact& two = mixed.contacts.append(2);
  two.body_a = two.shape_a = 2;
  two.body_b = two.shape_b = 3;
  CHECK(level_runs(mixed) == Runs{{0}, {3}, {1}, {4}, {2}});
  CHECK(level_runs(mixed, false) == Runs{{0}, {1}, {2}, {3}, {4}});
  // Islands {1, 2} and {5, 6} of one-point contacts about island {3, 4}, which has a two-point
  // contact (7): each levelled island's levels hold its own contacts only.
  Graph three(7, {{1, 0}, {2, 0}, {1, 2}, {3, 0}, {5, 0}, {6, 0}, {5, 6}});
  gp::Contact& pair = three.contacts.append(2);
  pair.body_a = pair.shape_a = 3;
  pair.body_b = pair.shape_b = 4;
  CHECK(level_runs(three) == Runs{{0, 1}, {2}, {3}, {7}, {4, 5}, {6}});
}

TEST_CASE("A large island is visited colour after colour, no colour sharing a movable body") {
  const std::size_t n = kColouredAbove + 10;
  const Graph g = chain(n);
  const std::vector<std::uint32_t> order = visits(g);
  // Greedy colouring of the chain in contact order: the ground contact 0 takes colour 0, then the
  // links alternate 1, 0, 1, ... (link i shares body i with link i - 1, and link 1 shares body 1
  // with the ground contact). Colour 0 is contact 0 and the even links, colour 1 the odd ones.
  std::vector<std::uint32_t> expected{0};
  for (std::uint32_t i = 2; i < g.contacts.size(); i += 2) expected.push_back(i);
  for (std::uint32_t i = 1; i < g.contacts.size(); i += 2) expected.push_back(i);
  CHECK(order == expected);
}

TEST_CASE("Contacts handed over at once have their one-point contacts first") {
  // A coloured chain whose every third link has two points, on one and two threads: each span
  // the pass hands over holds a run of one-point contacts, then only two-point ones.
  const std::size_t n = kColouredAbove + 100;
  Graph g(n + 1, {});
  for (gp::BodyId b = 1; b <= n; ++b) {
    gp::Contact& c = g.contacts.append(b % 3 == 0 ? 2 : 1);
    c.body_a = c.shape_a = b - 1;
    c.body_b = c.shape_b = b;
  }
  gp::ContactBatches batches;
  batches.build(g.contacts, {}, g.inertia, g.positions, {0, kColouredAbove});
  for (const int threads : {1, 2}) {
    std::atomic<int> spans = 0, mixed = 0, unordered = 0;
    tbb::task_arena(threads).execute([&] {
      batches.run([](std::uint32_t) { return 0.0; },
                  [&](std::span<const std::uint32_t> independent) {
                    const auto one_point = [&](std::uint32_t i) {
                      return g.contacts[i].count() == 1;
                    };
                    ++spans;
                    if (!std::all_of(independent.begin(), independent.end(), one_point) &&
                        std::any_of(independent.begin(), independent.end(), one_point)) {
                      ++mixed;
                    }
                    if (!std::is_partitioned(independent.begin(), independent.end(), one_point)) {
                      ++unordered;
                    }
                    return 0.0;
                  },
                  Visit{.by_levels = true});
    });
    INFO(threads << " threads");
    // Spans holding both kinds exist, so that the order within them is tested.
    CHECK(spans >= 2);
    CHECK(mixed > 0);
    CHECK(unordered == 0);
  }
}

TEST_CASE("The passes' largest value is the same on any number of threads") {
  const Graph g = chain(kColouredAbove + 100);
  gp::ContactBatches batches;
  batches.build(g.contacts, {}, g.inertia, g.positions, {0, kColouredAbove});
  const auto value = [](std::uint32_t i) { return static_cast<double>((i * 7919U) % 10007U); };
  const double one = tbb::task_arena(1).execute([&] { return batches.run(value); });
  const double two = tbb::task_arena(2).execute([&] { return batches.run(value); });
  double largest = 0.0;
  for (std::uint32_t i = 0; i < g.contacts.size(); ++i) largest = std::max(largest, value(i));
  CHECK(one == largest);
  CHECK(two == largest);
}

TEST_CASE("A stage with little beside its largest island stays on the calling thread") {
  // A chain of 3000 contacts and 200 islands of one contact each beside it (fewer than
  // kSharedStageContacts): on two threads every contact is solved by the thread that runs the
  // pass, where its caches hold them. With 2500 islands beside it the stage is shared, and the
  // visit is still every contact once.
  for (const std::size_t beside : {std::size_t{200}, std::size_t{2500}}) {
    const std::size_t chained = 3000;
    std::vector<std::pair<gp::BodyId, gp::BodyId>> links{{1, 0}};
    for (gp::BodyId b = 1; b < chained; ++b) links.emplace_back(b, b + 1);
    for (std::size_t k = 0; k < beside; ++k) {
      const auto first = static_cast<gp::BodyId>(chained + 1 + 2 * k);
      links.emplace_back(first, first + 1);
    }
    const Graph g(chained + 1 + 2 * beside, links);
    gp::ContactBatches batches;
    batches.build(g.contacts, {}, g.inertia, g.positions, {0, kColouredAbove});
    std::mutex guard;
    std::vector<std::thread::id> by;
    std::vector<int> seen(g.contacts.size(), 0);
    const std::thread::id caller = std::this_thread::get_id();
    tbb::task_arena(2).execute([&] {
      batches.run([&](std::uint32_t i) {
        // A few microseconds a contact, long enough for an idle worker to wake and take tasks.
        volatile double work = 0.0;
        for (int k = 0; k < 2000; ++k) work = work + 1.0;
        const std::lock_guard lock(guard);
        by.push_back(std::this_thread::get_id());
        ++seen[i];
        return 0.0;
      });
    });
    INFO(beside << " islands beside the chain");
    CHECK(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
    if (beside < gp::ContactBatches::kSharedStageContacts) {
      CHECK(std::all_of(by.begin(), by.end(), [&](std::thread::id t) { return t == caller; }));
    }
  }
}

TEST_CASE("A large island is visited part by part, then the contacts between parts") {
  // The chain of 8 bodies at x = 1..8, and its 8 contacts, parted above 3 contacts. In two parts,
  // {1..4} and {5..8}: contacts 0 (ground - 1) to 3 (3 - 4) inside the first, 5 to 7 inside the
  // second, and 4 (4 - 5) between them.
  const Graph g = chain(8);
  CHECK(visits(g, {3, 0}) == std::vector<std::uint32_t>{0, 1, 2, 3, 5, 6, 7, 4});
  // In four, {1, 2}, {3, 4}, {5, 6}, {7, 8}: contacts 0 and 1 (1 - 2) inside part 0, 3 inside
  // part 1, 5 inside part 2, 7 inside part 3; 2 (2 - 3) joins parts 0 and 1, 6 (6 - 7) parts 2
  // and 3, and 4 the two halves.
  CHECK(visits(g, kFourParts) == std::vector<std::uint32_t>{0, 1, 3, 5, 7, 2, 6, 4});
  // Under the threshold, or with parting off, the contacts' own order.
  CHECK(visits(g, {8, 0}) == in_order(8));
  CHECK(visits(g, {0, 0}) == in_order(8));
}

TEST_CASE("Two large islands are each cut in two, their parts side by side") {
  // Chains 1..8 (contacts 0..7) and 9..16 (contacts 8..15), each resting on the ground: each is
  // halved as the chain above, its parts' contacts first, island after island, then the contact
  // between each island's halves.
  std::vector<std::pair<gp::BodyId, gp::BodyId>> links;
  for (const gp::BodyId first : {1U, 9U}) {
    links.emplace_back(first, 0);
    for (gp::BodyId b = first; b < first + 7; ++b) links.emplace_back(b, b + 1);
  }
  const Graph g(17, links);
  CHECK(visits(g, {3, 0}) ==
        std::vector<std::uint32_t>{0, 1, 2, 3, 5, 6, 7, 8, 9, 10, 11, 13, 14, 15, 4, 12});
}

TEST_CASE("A chain is halved across its length, whatever order its bodies come in") {
  // The same chain standing upright (body b at (0, b)) and listed from the top: the same parts,
  // found by height, and the same order as along x.
  std::vector<std::pair<gp::BodyId, gp::BodyId>> links{{8, 0}};
  for (gp::BodyId b = 8; b > 1; --b) links.emplace_back(b, b - 1);
  Graph g(9, links);
  for (std::size_t b = 0; b < 9; ++b) g.positions[b] = {0.0, 9.0 - static_cast<double>(b)};
  // Bodies 8, 7 are at the bottom: parts {8, 7}, {6, 5}, {4, 3}, {2, 1}, contact k joining
  // bodies 9 - k and 8 - k.
  CHECK(visits(g, kFourParts) == std::vector<std::uint32_t>{0, 1, 3, 5, 7, 2, 6, 4});
}

TEST_CASE("A pyramid is cut between its layers, not through them") {
  // Box2D's pyramid of 20 rows: row r holds 20 - r unit bodies at x = r / 2 + j, y = r, each
  // resting on the two below it, touching its neighbours in the row, and row 0 on the ground
  // (body 0). It is 19 m wide and 19 m tall, but a cut at the median of x passes through every
  // row, where one at the median of y passes between two: rows 0 to 5 hold 20 + 19 + ... + 15 =
  // 105 bodies, half of the 210. Halved once, the contacts between the parts are then the
  // supports of row 6 on row 5, and no contact within a row.
  constexpr int kRows = 20;
  std::vector<std::vector<gp::BodyId>> id(kRows);
  gp::BodyId next = 1;
  for (int r = 0; r < kRows; ++r) {
    for (int j = 0; j < kRows - r; ++j) id[r].push_back(next++);
  }
  std::vector<std::pair<gp::BodyId, gp::BodyId>> links;
  std::vector<std::uint32_t> row6_on_row5;
  for (int r = 0; r < kRows; ++r) {
    for (int j = 0; j < kRows - r; ++j) {
      if (r == 0) links.emplace_back(id[r][j], 0);
      if (j > 0) links.emplace_back(id[r][j], id[r][j - 1]);
      for (int below : {j, j + 1}) {
        if (r == 0) continue;
        if (r == 6) row6_on_row5.push_back(static_cast<std::uint32_t>(links.size()));
        links.emplace_back(id[r][j], id[r - 1][below]);
      }
    }
  }
  Graph g(next, links);
  for (int r = 0; r < kRows; ++r) {
    for (int j = 0; j < kRows - r; ++j) g.positions[id[r][j]] = {0.5 * r + j, r};
  }
  const std::vector<std::uint32_t> order = visits(g, {links.size() / 2, 0});
  REQUIRE(order.size() == links.size());
  std::vector<std::uint32_t> last(order.end() - static_cast<std::ptrdiff_t>(row6_on_row5.size()),
                                  order.end());
  CHECK(last == row6_on_row5);
}

// The contacts run_in_stretches hands over on `threads` threads, stretch after stretch, how
// many stretches, and what it returned of the stretches' largest contact indices.
struct Stretches {
  std::vector<std::uint32_t> contacts;
  std::size_t count = 0;
  double largest = 0.0;
};

Stretches stretches_of(const Graph& g, gp::IslandSplitting splitting, int threads = 1) {
  gp::ContactBatches batches;
  batches.build(g.contacts, {}, g.inertia, g.positions, splitting);
  Stretches found;
  std::mutex taking;
  tbb::task_arena(threads).execute([&] {
    found.largest = batches.run_in_stretches([&](std::span<const std::uint32_t> stretch) {
      const std::lock_guard<std::mutex> lock(taking);
      found.contacts.insert(found.contacts.end(), stretch.begin(), stretch.end());
      ++found.count;
      return static_cast<double>(*std::max_element(stretch.begin(), stretch.end()));
    });
  });
  return found;
}

TEST_CASE("In stretches, the contacts come in the order of the visit one at a time") {
  // Levelled islands (one-point contacts), an island parted, and one coloured: on one thread the
  // stretches hold every contact once, in the order visits() gives.
  const Graph row(4, {{1, 0}, {2, 0}, {3, 0}, {1, 2}, {2, 3}});
  CHECK(stretches_of(row, {0, kColouredAbove}).contacts == visits(row));
  const Graph parted = chain(8);
  const Stretches parts = stretches_of(parted, kFourParts);
  CHECK(parts.contacts == std::vector<std::uint32_t>{0, 1, 3, 5, 7, 2, 6, 4});
  // The parts, then the contacts between them: two stages, two stretches on one thread.
  CHECK(parts.count == 2);
  const Graph coloured = chain(kColouredAbove + 10);
  CHECK(stretches_of(coloured, {0, kColouredAbove}).contacts == visits(coloured));
  // On two threads, every contact once still.
  const Stretches on_two = stretches_of(coloured, {0, kColouredAbove}, 2);
  std::vector<std::uint32_t> shared = on_two.contacts;
  std::sort(shared.begin(), shared.end());
  CHECK(shared == in_order(coloured.contacts.size()));
  // What it returns: the largest of what the stretches returned, on one thread or two.
  const auto last = static_cast<double>(coloured.contacts.size() - 1);
  CHECK(on_two.largest == last);
  CHECK(stretches_of(coloured, {0, kColouredAbove}).largest == last);
  CHECK(parts.largest == static_cast<double>(parted.contacts.size() - 1));
}

TEST_CASE("Colouring an island takes precedence over parting it") {
  const Graph g = chain(kColouredAbove + 10);
  CHECK(visits(g, {64, kColouredAbove}) == visits(g, {0, kColouredAbove}));
}

TEST_CASE(
    "A body whose place is not a number leaves every contact of a parted island visited once") {
  Graph g = chain(8);
  g.positions[3].x() = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::uint32_t> order = visits(g, kFourParts);
  std::sort(order.begin(), order.end());
  CHECK(order == in_order(8));
}

// The points of `g`'s contacts as the end of a pass keeps them.
std::vector<gp::WarmStart> kept(const Graph& g) {
  std::vector<gp::WarmStart> points;
  gp::keep_impulses(g.contacts, points);
  return points;
}

TEST_CASE("The contacts of the last pass keep their parts though the bodies moved") {
  // The chain of 8 bodies parted in four (see above); then each body moves one place along x,
  // the last two to the front, so that parts found afresh would be {7, 8}, {1, 2}, {3, 4}, {5, 6}.
  Graph g = chain(8);
  gp::ContactBatches batches;
  const std::vector<std::uint32_t> before = visits(batches, g, kFourParts);
  for (std::size_t b = 1; b < 9; ++b) g.positions[b].x() = static_cast<double>((b + 1) % 8);
  REQUIRE(visits(g, kFourParts) != before);
  CHECK(visits(batches, g, kFourParts, kept(g)) == before);
  // Unless the points kept are not theirs, or they were parted in another number of parts.
  CHECK(visits(batches, g, kFourParts) == visits(g, kFourParts));
  CHECK(visits(batches, g, {3, 0}, kept(g)) == visits(g, {3, 0}));
}

TEST_CASE("Other contacts than the last pass's are grouped afresh") {
  gp::ContactBatches batches;
  // Bodies 1..4 on the ground, 1 - 2 and 3 - 4 linked; then 2 - 3 instead of 3 - 4.
  const Graph first(5, {{1, 0}, {3, 4}, {2, 1}, {3, 0}, {4, 0}});
  REQUIRE(visits(batches, first, {0, kColouredAbove}) == visits(first));
  const Graph second(5, {{1, 0}, {2, 3}, {2, 1}, {3, 0}, {4, 0}});
  CHECK(visits(batches, second, {0, kColouredAbove}, kept(first)) == visits(second));
}

TEST_CASE("A body that stops moving splits its island though the contacts stay") {
  // A chain of 4, then body 2 held (as a body falling asleep or removed is): the islands {1}
  // (its contacts with the ground and with body 2) and {3, 4}, of 2 points each, where there was
  // one of 4.
  Graph g = chain(4);
  gp::ContactBatches batches;
  batches.build(g.contacts, {}, g.inertia, g.positions, {0, kColouredAbove});
  REQUIRE(batches.islands().points[1] == 4);
  g.inertia.inverse_mass[2] = g.inertia.inverse_moment[2] = 0.0;
  batches.build(g.contacts, kept(g), g.inertia, g.positions, {0, kColouredAbove});
  CHECK(batches.islands().points[1] == 2);
  CHECK(batches.islands().points[3] == 2);
}

TEST_CASE("A contact that gained a point since the last pass is counted in its island") {
  Graph g = chain(3);
  gp::ContactBatches batches;
  batches.build(g.contacts, {}, g.inertia, g.positions, {0, kColouredAbove});
  REQUIRE(batches.islands().points[1] == 3);
  // The same pairs, the second contact with two points.
  gp::ContactSet two_points;
  for (std::size_t i = 0; i < g.contacts.size(); ++i) {
    gp::Contact& c = two_points.append(i == 1 ? 2 : 1);
    c.body_a = c.shape_a = g.contacts[i].body_a;
    c.body_b = c.shape_b = g.contacts[i].body_b;
  }
  batches.build(two_points, kept(g), g.inertia, g.positions, {0, kColouredAbove});
  CHECK(batches.islands().points[1] == 4);
}

}  // namespace test_contact_batches
}  // namespace
