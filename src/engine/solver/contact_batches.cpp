#include "engine/solver/contact_batches.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>

#include <tbb/parallel_invoke.h>

#include "engine/capacity.hpp"

namespace gp {

namespace {

// Colours a large island's contacts take; a contact that finds all of them taken by its bodies
// goes to one more, whose contacts are solved one after the other.
constexpr std::size_t kColours = 64;
// Contacts or bodies whose build is checked by a thread at a time (a few nanoseconds each, a task
// about a microsecond to hand out), and how many make the check worth sharing out.
constexpr std::size_t kCheckedPerTask = 2048;
constexpr std::size_t kParallelChecks = 8192;

// A movable body of an island being cut, with its place, read once: the halving then walks an
// array rather than the bodies' places at random. A place that is not a number (a step about to
// report it) counts as infinite, so that the order stays strict and nth_element within its range.
struct PlacedBody {
  Vec2 place;
  BodyId body;
};

PlacedBody placed_body(std::span<const Vec2> positions, BodyId b) {
  const auto finite = [](double x) {
    return std::isnan(x) ? std::numeric_limits<double>::infinity() : x;
  };
  return {{finite(positions[b].x()), finite(positions[b].y())}, b};
}

// Halves `bodies` `depth` times, and gives each body its part, as halving bits under `code`, in
// `part_of`.
void halve_bodies(std::span<PlacedBody> bodies, int depth, std::uint32_t code,
                  std::span<std::uint32_t> part_of) {
  if (depth == 0) {
    for (const PlacedBody& b : bodies) part_of[b.body] = code;
    return;
  }
  const std::size_t middle = bodies.size() / 2;
  // At the median along x or y, whichever cut is shorter, so that it meets fewer contacts and
  // the halves' bodies mix less in memory: between a pile's layers rather than through them all.
  // A cut's length is taken through the bodies' centre: the spread, along the cut, of the bodies
  // within a twentieth of their extent of it, which two linear passes find (ranking the bodies
  // about each median would take selections, costly in mispredicted branches). On a tie, or a
  // length that is not a number, along x. Ties by body id, so that the halves do not depend on
  // the order the bodies were listed in.
  if (bodies.size() > 1) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    Vec2 sum = Vec2::Zero();
    Vec2 low{kInf, kInf};
    Vec2 high{-kInf, -kInf};
    for (const PlacedBody& b : bodies) {
      sum += b.place;
      low = low.cwiseMin(b.place);
      high = high.cwiseMax(b.place);
    }
    const Vec2 centre = sum / static_cast<double>(bodies.size());
    const Vec2 reach = (high - low) / 20.0;
    // Per axis of the cut's normal: the lowest and highest place along the cut.
    Vec2 cut_low{kInf, kInf};
    Vec2 cut_high{-kInf, -kInf};
    for (const PlacedBody& b : bodies) {
      const Vec2& p = b.place;
      for (int axis = 0; axis < 2; ++axis) {
        if (!(std::abs(p[axis] - centre[axis]) <= reach[axis])) continue;
        cut_low[axis] = std::min(cut_low[axis], p[1 - axis]);
        cut_high[axis] = std::max(cut_high[axis], p[1 - axis]);
      }
    }
    // No body near the centre: the cut there crosses a gap, and meets nothing.
    const auto length = [&](int axis) {
      return cut_high[axis] >= cut_low[axis] ? cut_high[axis] - cut_low[axis] : 0.0;
    };
    const int axis = length(1) < length(0) ? 1 : 0;
    std::nth_element(bodies.begin(), bodies.begin() + static_cast<std::ptrdiff_t>(middle),
                     bodies.end(), [axis](const PlacedBody& a, const PlacedBody& b) {
                       const double pa = a.place[axis];
                       const double pb = b.place[axis];
                       return pa < pb || (pa == pb && a.body < b.body);
                     });
  }
  // The halves hold different bodies: each is cut on a thread of its own, with the same result.
  // On one thread, without handing out tasks, whose pool the heap would keep.
  const auto lower = [&] { halve_bodies(bodies.first(middle), depth - 1, 2 * code, part_of); };
  const auto upper = [&] {
    halve_bodies(bodies.subspan(middle), depth - 1, 2 * code + 1, part_of);
  };
  if (one_thread()) {
    lower();
    upper();
  } else {
    tbb::parallel_invoke(lower, upper);
  }
}

}  // namespace

void ContactBatches::build(const ContactSet& contacts, std::span<const WarmStart> last_kept,
                           const BodyInertia& inertia, std::span<const Vec2> positions,
                           const IslandSplitting& splitting) {
  stored_ = false;
  if (holds_for(contacts, last_kept, inertia, splitting)) return;
  // The last build's places are found anew; their room serves the build as scratch.
  if (stored_at_.capacity() > contact_scratch_.capacity()) stored_at_.swap(contact_scratch_);
  stored_at_.clear();
  islands_.find(contacts, inertia);
  order_.clear();
  task_end_.clear();
  stage_end_.clear();
  parted_.clear();
  const std::size_t bodies = inertia.inverse_mass.size();
  const auto contacts_in = [this](std::size_t root) {
    return islands_.island_end[root] - islands_.island_start[root];
  };
  bool any_coloured = false;
  level_end_.clear();
  levels_of_.clear();
  // Levelling starts from bodies without levels: before the islands not cut, and again before the
  // parts, as parting leaves its codes in the body scratch.
  const auto start_levelling = [this, bodies] {
    body_scratch_.assign(bodies, 0);
    level_base_ = 0;
  };
  start_levelling();
  for (const BodyId r : islands_.roots) {
    const std::uint32_t start = islands_.island_start[r];
    const std::uint32_t end = islands_.island_end[r];
    if (splitting.coloured_above > 0 && contacts_in(r) > splitting.coloured_above) {
      any_coloured = true;
    } else if (splitting.parted_above > 0 && contacts_in(r) > splitting.parted_above) {
      parted_.push_back({r, 0, 0});
    } else {
      order_.resize(order_.size() + (end - start));
      task_end_.push_back(static_cast<std::uint32_t>(order_.size()));
      place_task(contacts, {islands_.order.data() + start, end - start});
    }
  }
  part(contacts, inertia, positions, splitting.parts);
  first_colour_stage_ = stage_end_.size();
  // The parts' tasks, placed from a copy of their contacts (part leaves room for all of them).
  if (levels_of_.size() < task_end_.size()) start_levelling();
  while (levels_of_.size() < task_end_.size()) {
    const std::size_t t = levels_of_.size();
    const std::uint32_t begin = t == 0 ? 0 : task_end_[t - 1];
    const std::uint32_t count = task_end_[t] - begin;
    std::copy_n(order_.begin() + begin, count, contact_scratch_.begin());
    place_task(contacts, {contact_scratch_.data(), count});
  }
  if (any_coloured) colour(contacts, inertia, splitting.coloured_above);
  choose_shared_stages();
  if (contacts.single_points() && contacts.size() > splitting.stored_in_order_above &&
      order_.size() == contacts.size()) {
    index_in_storage_order();
  }
}

void ContactBatches::index_in_storage_order() {
  // In the scratch's room, which the build no longer needs: one array a contact, not two.
  stored_at_.swap(contact_scratch_);
  stored_at_.resize(order_.size());
  for (std::uint32_t e = 0; e < order_.size(); ++e) stored_at_[order_[e]] = e;
  for (std::uint32_t& i : islands_.order) i = stored_at_[i];
  std::iota(order_.begin(), order_.end(), std::uint32_t{0});
}

void ContactBatches::store_in_order(ContactSet& contacts) {
  if (stored_at_.empty()) return;
  contacts.reorder(stored_at_, moved_);
  stored_ = true;
}

void ContactBatches::restore_order(ContactSet& contacts) {
  if (!stored_) return;
  contacts.restore_order(stored_at_, moved_);
  stored_ = false;
}

void ContactBatches::choose_shared_stages() {
  shared_stage_.clear();
  std::size_t first = 0;
  for (const std::uint32_t last : stage_end_) {
    std::uint32_t largest = 0;
    std::uint32_t all = 0;
    for (std::size_t t = first; t < last; ++t) {
      const std::uint32_t size = task_end_[t] - (t == 0 ? 0 : task_end_[t - 1]);
      largest = std::max(largest, size);
      all += size;
    }
    shared_stage_.push_back(all - largest >= kSharedStageContacts ? 1 : 0);
    first = last;
  }
}

bool ContactBatches::holds_for(const ContactSet& contacts, std::span<const WarmStart> last_kept,
                               const BodyInertia& inertia, const IslandSplitting& splitting) {
  const std::size_t bodies = inertia.inverse_mass.size();
  bool same = built_contacts_ == contacts.size() && last_kept.size() == contacts.point_count() &&
              movable_.size() == bodies &&
              built_splitting_.parted_above == splitting.parted_above &&
              built_splitting_.coloured_above == splitting.coloured_above &&
              built_splitting_.parts == splitting.parts &&
              built_splitting_.stored_in_order_above == splitting.stored_in_order_above;
  // Pairs are unique and the points kept in the contacts' order: each contact's points finding
  // its own pair where they were kept makes the two lists of contacts the same.
  const auto pairs_kept = [&](std::size_t first, std::size_t last, bool kept) {
    for (std::size_t i = first; kept && i < last; ++i) {
      const Contact& c = contacts[i];
      const std::uint64_t pair = WarmStart::pair_key({c.shape_a, c.shape_b});
      for (int k = 0; k < c.count(); ++k)
        kept = kept && last_kept[c.first_point + k].pair() == pair;
    }
    return kept;
  };
  const auto movable_kept = [&](std::size_t first, std::size_t last, bool kept) {
    for (auto b = static_cast<BodyId>(first); kept && b < last; ++b) {
      kept = (movable_[b] != 0) == movable(inertia, b);
    }
    return kept;
  };
  const auto both = [](bool a, bool b) { return a && b; };
  same = same &&
         reduce_blocks(contacts.size(), kCheckedPerTask, contacts.size() < kParallelChecks, true,
                       pairs_kept, both) &&
         reduce_blocks(bodies, kCheckedPerTask, bodies < kParallelChecks, true, movable_kept, both);
  if (same) return true;
  built_contacts_ = contacts.size();
  reserve_for(movable_, bodies);
  movable_.resize(bodies);
  for (BodyId b = 0; b < bodies; ++b) movable_[b] = movable(inertia, b) ? 1 : 0;
  built_splitting_ = splitting;
  return false;
}

void ContactBatches::part(const ContactSet& contacts, const BodyInertia& inertia,
                          std::span<const Vec2> positions, std::size_t parts) {
  const auto close_stage = [this] {
    stage_end_.push_back(static_cast<std::uint32_t>(task_end_.size()));
  };
  if (parted_.empty()) {
    close_stage();
    return;
  }
  const std::size_t bodies = inertia.inverse_mass.size();
  body_scratch_.resize(bodies);
  contact_scratch_.resize(contacts.size());
  // The islands' movable bodies, island after island, each in the order of their ids: found in a
  // pass over the bodies, whose island is their root, where an island's contacts would list them
  // in a walk over the bodies at random. Freed when done: held from step to step, it would hold
  // 24 B a body.
  constexpr std::uint32_t kNotParted = ~std::uint32_t{0};
  const auto island_of = [this](BodyId root) {
    const auto found = std::ranges::lower_bound(parted_, root, {}, &PartedIsland::root);
    return found != parted_.end() && found->root == root
               ? static_cast<std::uint32_t>(found - parted_.begin())
               : kNotParted;
  };
  std::vector<std::uint32_t> placed_end(parted_.size() + 1, 0);
  for (BodyId b = 0; b < bodies; ++b) {
    const std::uint32_t k = movable(inertia, b) ? island_of(islands_.parent[b]) : kNotParted;
    body_scratch_[b] = k;
    if (k != kNotParted) ++placed_end[k + 1];
  }
  std::partial_sum(placed_end.begin(), placed_end.end(), placed_end.begin());
  std::vector<PlacedBody> placed(placed_end.back());
  std::vector<std::uint32_t> next(placed_end.begin(), placed_end.end() - 1);
  for (BodyId b = 0; b < bodies; ++b) {
    if (body_scratch_[b] != kNotParted)
      placed[next[body_scratch_[b]]++] = placed_body(positions, b);
  }
  const int depth = std::clamp(static_cast<int>(std::bit_width(parts)) - 1, 1, kMaxPartDepth);
  std::size_t groups = 0;
  for (std::size_t k = 0; k < parted_.size(); ++k) {
    PartedIsland& island = parted_[k];
    const std::uint32_t start = islands_.island_start[island.root];
    const std::uint32_t end = islands_.island_end[island.root];
    halve_bodies(std::span(placed).subspan(placed_end[k], placed_end[k + 1] - placed_end[k]), depth,
                 0, body_scratch_);
    island.depth = depth;
    island.first_group = groups;
    groups += std::size_t{2} << depth;
    // A contact's group: its part, or, between two parts, the smallest group of parts holding
    // both, whose heap number is their codes' common leading bits under a leading 1.
    for (std::uint32_t e = start; e < end; ++e) {
      const Contact& c = contacts[islands_.order[e]];
      const std::uint32_t a = body_scratch_[movable(inertia, c.body_a) ? c.body_a : c.body_b];
      const std::uint32_t b = body_scratch_[movable(inertia, c.body_b) ? c.body_b : c.body_a];
      const int shift = std::bit_width(a ^ b);
      contact_scratch_[islands_.order[e]] = ((std::uint32_t{1} << depth) | a) >> shift;
    }
  }
  group_start_.assign(groups, 0);
  for (const PartedIsland& island : parted_) {
    for (std::uint32_t e = islands_.island_start[island.root]; e < islands_.island_end[island.root];
         ++e) {
      ++group_start_[island.first_group + contact_scratch_[islands_.order[e]]];
    }
  }
  // The parts first, beside the islands not cut; then, one task per island, the contacts between
  // its parts, group by group from the smallest up. Its groups of a size share no body and could
  // run side by side, but they hold a few per cent of the contacts, less than a stage costs.
  auto cursor = static_cast<std::uint32_t>(order_.size());
  const auto place = [&](const PartedIsland& island, std::size_t level, bool task_each) {
    for (std::size_t g = std::size_t{1} << level; g < std::size_t{2} << level; ++g) {
      std::uint32_t& slot = group_start_[island.first_group + g];
      const std::uint32_t count = slot;
      slot = cursor;
      cursor += count;
      if (task_each && count > 0) task_end_.push_back(cursor);
    }
  };
  for (const PartedIsland& island : parted_) place(island, island.depth, true);
  close_stage();
  for (const PartedIsland& island : parted_) {
    const std::uint32_t first = cursor;
    for (int level = island.depth - 1; level >= 0; --level) {
      place(island, static_cast<std::size_t>(level), false);
    }
    if (cursor > first) task_end_.push_back(cursor);
  }
  close_stage();
  order_.resize(cursor);
  for (const PartedIsland& island : parted_) {
    for (std::uint32_t e = islands_.island_start[island.root]; e < islands_.island_end[island.root];
         ++e) {
      const std::uint32_t i = islands_.order[e];
      order_[group_start_[island.first_group + contact_scratch_[i]]++] = i;
    }
  }
}

void ContactBatches::place_task(const ContactSet& contacts, std::span<const std::uint32_t> task) {
  const std::size_t t = levels_of_.size();
  const std::uint32_t begin = t == 0 ? 0 : task_end_[t - 1];
  const auto first = static_cast<std::uint32_t>(level_end_.size());
  // A contact's level, from 1, as its bodies' last contacts left them; its bodies then take it.
  // Bodies keep their levels above level_base_, which each pass raises past the levels it gave
  // out: no pass over the task to clear them.
  const auto level_of = [&](const Contact& c) {
    const bool a = movable_[c.body_a] != 0;
    const bool b = movable_[c.body_b] != 0;
    const std::uint32_t level = 1 + std::max({level_base_, a ? body_scratch_[c.body_a] : 0,
                                              b ? body_scratch_[c.body_b] : 0});
    if (a) body_scratch_[c.body_a] = level;
    if (b) body_scratch_[c.body_b] = level;
    return level - level_base_;
  };
  // The levels are found twice, to count each level's contacts and then to place them: a second
  // pass over the task costs less than the room for each contact's level.
  bool levelled = true;
  for (const std::uint32_t i : task) {
    const Contact& c = contacts[i];
    levelled = c.count() == 1;
    if (!levelled) break;
    const std::uint32_t level = level_of(c);
    if (first + level > level_end_.size()) append(level_end_, 0);
    ++level_end_[first + level - 1];
  }
  level_base_ += static_cast<std::uint32_t>(level_end_.size() - first);
  if (!levelled) {
    level_end_.resize(first);
    std::copy(task.begin(), task.end(), order_.begin() + begin);
    append(levels_of_, {});
    return;
  }
  // Each level's count into where it starts, and, as its contacts are placed, where it ends.
  std::uint32_t start = begin;
  for (std::size_t l = first; l < level_end_.size(); ++l) {
    const std::uint32_t count = level_end_[l];
    level_end_[l] = start;
    start += count;
  }
  for (const std::uint32_t i : task) order_[level_end_[first + level_of(contacts[i]) - 1]++] = i;
  level_base_ += static_cast<std::uint32_t>(level_end_.size() - first);
  append(levels_of_, {first, static_cast<std::uint32_t>(level_end_.size())});
}

void ContactBatches::colour(const ContactSet& contacts, const BodyInertia& inertia,
                            std::size_t coloured_above) {
  const std::size_t bodies = inertia.inverse_mass.size();
  const auto large = [this, coloured_above](std::size_t root) {
    return islands_.island_end[root] - islands_.island_start[root] > coloured_above;
  };
  // Greedy colouring in the contacts' order: each contact takes the lowest colour that no other
  // contact of its movable bodies has. Static and kinematic bodies take any number of contacts
  // of a colour, as the solver only reads their motion.
  colours_.assign(bodies, 0);
  bucket_.resize(contacts.size());
  // Contacts go to bucket 2k (colour k, one point) or 2k + 1 (colour k, two points): a colour's
  // one-point contacts side by side, for solve_single_points. The contacts that found every colour
  // taken go to the last bucket.
  constexpr std::size_t kLastBucket = 2 * kColours;
  std::array<std::uint32_t, kLastBucket + 3> next{};  // counts, then starts
  for (const BodyId r : islands_.roots) {
    if (!large(r)) continue;
    for (std::uint32_t e = islands_.island_start[r]; e < islands_.island_end[r]; ++e) {
      const Contact& c = contacts[islands_.order[e]];
      const bool a = movable(inertia, c.body_a);
      const bool b = movable(inertia, c.body_b);
      const std::uint64_t taken = (a ? colours_[c.body_a] : 0) | (b ? colours_[c.body_b] : 0);
      const auto colour = static_cast<std::size_t>(std::countr_one(taken));
      std::size_t bucket = kLastBucket;
      if (colour < kColours) {
        if (a) colours_[c.body_a] |= std::uint64_t{1} << colour;
        if (b) colours_[c.body_b] |= std::uint64_t{1} << colour;
        bucket = 2 * colour + (c.count() == 1 ? 0 : 1);
      }
      bucket_[islands_.order[e]] = static_cast<std::uint8_t>(bucket);
      ++next[bucket + 2];
    }
  }
  // Counting sort by bucket, each bucket's contacts in the contacts' order.
  const auto base = static_cast<std::uint32_t>(order_.size());
  next[1] = base;
  for (std::size_t k = 2; k < next.size(); ++k) next[k] += next[k - 1];
  order_.resize(next.back());
  for (const BodyId r : islands_.roots) {
    if (!large(r)) continue;
    for (std::uint32_t e = islands_.island_start[r]; e < islands_.island_end[r]; ++e) {
      const std::uint32_t i = islands_.order[e];
      order_[next[bucket_[i] + 1]++] = i;
    }
  }
  // next[k + 1] is now the end of bucket k: colour k ends at next[2k + 2].
  for (std::size_t k = 0; k < kColours; ++k) {
    const std::uint32_t begin = k == 0 ? base : next[2 * k];
    const std::uint32_t end = next[2 * k + 2];
    for (std::uint32_t e = begin; e < end; ++e) task_end_.push_back(e + 1);
    stage_end_.push_back(static_cast<std::uint32_t>(task_end_.size()));
  }
  if (next[kLastBucket + 1] > next[kLastBucket]) task_end_.push_back(next[kLastBucket + 1]);
  stage_end_.push_back(static_cast<std::uint32_t>(task_end_.size()));
}

}  // namespace gp
