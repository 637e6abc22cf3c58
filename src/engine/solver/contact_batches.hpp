#pragma once
// The order in which the contact passes visit a step's contacts, and which of them may be solved
// side by side on several threads. Each island is solved on its own, in the contacts' order, as
// one thread would. An island of more contacts than Settings::island_part_contacts is cut into
// parts by its bodies' places, the parts solved side by side, each in the contacts' order, and
// then the contacts that join them; one of more than Settings::coloured_island_contacts (when
// set) is graph-coloured instead, so that its contacts are solved colour after colour, the
// contacts of a colour side by side. The order depends on the contacts and on the bodies' places
// at the step the contacts last changed, never on the number of threads, so a step gives the same
// result to the bit on any number of them.

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "engine/solver/contact_islands.hpp"
#include "engine/solver/warm_start.hpp"
#include "engine/threads.hpp"
#include "scene/settings.hpp"

namespace gp {

/// The contacts in the order of a single thread, for the passes run outside the step's solver
/// (impacts, speculative contacts) and by tests: ContactBatches' interface, one contact after
/// the other.
class ContactsInOrder {
 public:
  explicit ContactsInOrder(const ContactSet& contacts) : size_(contacts.size()) {}

  /// The largest value `solve(contact index)` returns over the contacts, called in their order.
  template <typename Solve>
  double run(const Solve& solve) const {
    double largest = 0.0;
    for (std::uint32_t i = 0; i < size_; ++i) largest = std::max(largest, solve(i));
    return largest;
  }

 private:
  std::size_t size_;
};

/// Which islands ContactBatches cuts into parts or colours, by their number of contacts (0:
/// none), and which sets of contacts it stores in the order of solving.
struct IslandSplitting {
  std::size_t parted_above = 0;    ///< Settings::island_part_contacts
  std::size_t coloured_above = 0;  ///< Settings::coloured_island_contacts, before parting
  /// Settings::stored_in_order_contacts; by default none.
  std::size_t stored_in_order_above = std::numeric_limits<std::size_t>::max();
  /// Settings::island_parts: a power of two, from 2 to 2^ContactBatches::kMaxPartDepth.
  std::size_t parts = 2;
};

class ContactBatches {
 public:
  /// Contacts of a colour a thread takes at a time.
  static constexpr std::size_t kContactsPerChunk = 128;
  /// A stage whose tasks beside its largest hold fewer contacts is solved on one thread: sharing
  /// a stage costs the threads a meeting of some microseconds, what a thread takes to solve about
  /// this many contacts, and an island's contacts solved on the other core leave its caches.
  static constexpr std::size_t kSharedStageContacts = 2048;
  /// The most halvings of an island: into Settings::kMaxIslandParts parts.
  static constexpr int kMaxPartDepth =
      std::countr_zero(static_cast<unsigned>(Settings::kMaxIslandParts));

  /// Groups `contacts`, whose bodies are at `positions` [m, by body id], into stages of tasks.
  /// First stage: each island not cut, and each part of the cut ones. An island to part is halved
  /// at the median of its bodies' places along x or y, whichever cut is shorter (the spread along
  /// it, through their centre, of the bodies within a twentieth of their extent of it), and each
  /// half again, until there are `splitting.parts` parts; a contact
  /// between two parts joins the smallest group of parts holding both. Second stage: per cut
  /// island, one task of its contacts between parts, group by group from the smallest up. Last
  /// stages: each colour of the coloured islands, one task per contact. No two tasks of a stage
  /// share a body that the solver moves. The contacts of a task of the first two stages whose
  /// contacts all have one point are put in levels (Visit), level after level. Reuses its arrays'
  /// room. `last_kept` are the points of the contacts of the last pass, as keep_impulses kept them:
  /// when `contacts` are those same contacts (the same pairs of shapes, as many points each) as the
  /// last build's, the bodies as movable and the splitting the same (a pile at rest), the islands,
  /// parts, levels and colours of the last build are kept.
  void build(const ContactSet& contacts, std::span<const WarmStart> last_kept,
             const BodyInertia& inertia, std::span<const Vec2> positions,
             const IslandSplitting& splitting);

  /// The islands of the contacts build was given; once store_in_order has moved them, of the
  /// contacts where it put them.
  const ContactIslands& islands() const { return islands_; }

  /// Moves `contacts`, those build was given, to the order in which the passes visit them, where
  /// build chose to (a set of one-point contacts of more than splitting.stored_in_order_above,
  /// every contact in an island): the passes then
  /// walk them one after the other instead of gathering them from the whole set. The result is the
  /// same to the bit, as the passes visit the same contacts in the same order. Until
  /// restore_order, contact indices (of the passes, the islands and the contact set) are those of
  /// that order, and stored_at() gives, per contact of the contacts' own order, its index.
  void store_in_order(ContactSet& contacts);
  /// Puts `contacts` back in their own order (by pair of shapes), if store_in_order moved them.
  void restore_order(ContactSet& contacts);
  /// While the contacts are stored in order: per contact of their own order, its index in that
  /// order; else empty.
  std::span<const std::uint32_t> stored_at() const {
    return stored_ ? std::span<const std::uint32_t>(stored_at_) : std::span<const std::uint32_t>();
  }

  /// How a pass visits a task's contacts. Levels: a contact's level is one more than the highest
  /// level of the task's contacts before it that share a movable body with it. A level's contacts
  /// share none, and each body meets its contacts in the contacts' order, so that level by level
  /// they give the same result to the bit as in order, each level's contacts free to be solved
  /// at once. Interleaved halves (the first, the first past the middle, the second, ...):
  /// contacts next to each other in the contacts' order often share a body (a shape's contacts
  /// follow one another), so that each solve that moves bodies waits on the one before; from
  /// halves apart they seldom do, and the processor overlaps two solves, where passes that only
  /// read bodies lose by it the one stream of memory they walk.
  struct Visit {
    /// A task of one-point contacts level by level, each level to solve_independent.
    bool by_levels = false;
    /// The other tasks' contacts in two interleaved halves, else in order.
    bool interleaved = false;
    /// Each block of tasks a thread takes, its contacts in order, whole to solve_independent,
    /// which must then take them in their order (run_in_stretches).
    bool whole_blocks = false;
  };

  /// The largest value `solve(contact index)` returns over the contacts: stage after stage, the
  /// tasks of a stage on the threads the current task arena allows, a task's contacts in order (a
  /// task of one-point contacts in its levels' order, which gives the same result).
  template <typename Solve>
  double run(const Solve& solve) const {
    return run(
        solve,
        [&](std::span<const std::uint32_t> contacts) {
          double largest = 0.0;
          for (const std::uint32_t i : contacts) largest = std::max(largest, solve(i));
          return largest;
        },
        Visit{});
  }

  /// run(solve)'s visit, a stretch of contacts at a time: `solve_stretch(contact indices)` takes
  /// the contacts of the tasks of a stage that a thread takes together, or of a colour's block,
  /// in their order. A pass can then do what each contact needs alone for several contacts at
  /// once, overlapping their chains of divisions, before what must follow their order. Returns
  /// the largest value solve_stretch returns.
  template <typename SolveStretch>
  double run_in_stretches(const SolveStretch& solve_stretch) const {
    return run([](std::uint32_t) { return 0.0; }, solve_stretch, Visit{.whole_blocks = true});
  }

  /// The same, a task's contacts visited as `visit` says, but contacts that share no movable body
  /// (a colour's, a block at a time, and a level's) go to `solve_independent(contact indices)`,
  /// which returns the largest value over them: they may be solved in any order, or several at
  /// once, with the same result. Their one-point contacts come first.
  template <typename Solve, typename SolveIndependent>
  double run(const Solve& solve, const SolveIndependent& solve_independent, Visit visit) const {
    const auto entries = [this](std::uint32_t begin, std::uint32_t end) {
      return std::span<const std::uint32_t>(order_.data() + begin, end - begin);
    };
    const auto tasks = [&](std::size_t first, std::size_t last, double largest) {
      // The tasks of a block follow one another in order_: whole, or in order in one loop.
      const std::uint32_t block_begin = first == 0 ? 0 : task_end_[first - 1];
      const std::uint32_t block_end = task_end_[last - 1];
      if (visit.whole_blocks) {
        return std::max(largest, solve_independent(entries(block_begin, block_end)));
      }
      if (!visit.by_levels && !visit.interleaved) {
        for (std::uint32_t e = block_begin; e < block_end; ++e)
          largest = std::max(largest, solve(order_[e]));
        return largest;
      }
      for (std::size_t t = first; t < last; ++t) {
        const std::uint32_t begin = t == 0 ? 0 : task_end_[t - 1];
        const std::uint32_t end = task_end_[t];
        if (visit.by_levels && levelled(t)) {
          for (std::uint32_t l = levels_of_[t].first, level = begin; l < levels_of_[t].last; ++l) {
            largest = std::max(largest, solve_independent(entries(level, level_end_[l])));
            level = level_end_[l];
          }
          continue;
        }
        if (!visit.interleaved) {
          for (std::uint32_t e = begin; e < end; ++e) largest = std::max(largest, solve(order_[e]));
          continue;
        }
        const std::uint32_t middle = begin + (end - begin + 1) / 2;
        for (std::uint32_t e = begin, f = middle; e < middle; ++e, ++f) {
          largest = std::max(largest, solve(order_[e]));
          if (f < end) largest = std::max(largest, solve(order_[f]));
        }
      }
      return largest;
    };
    // A colour's tasks are one contact each, one after the other in order_.
    const auto colour_tasks = [&](std::size_t first, std::size_t last, double largest) {
      const std::uint32_t begin = first == 0 ? 0 : task_end_[first - 1];
      return std::max(largest, solve_independent(entries(begin, task_end_[last - 1])));
    };
    const bool alone = one_thread();
    double largest = 0.0;
    std::size_t first = 0;
    for (std::size_t stage = 0; stage < stage_end_.size(); ++stage) {
      const std::uint32_t last = stage_end_[stage];
      if (first == last) continue;
      // An island or a part is a task of its own; a colour's contacts, each a task of tens of
      // nanoseconds, are handed out by the hundred, as each hand-out costs about a microsecond.
      // The last colour takes the contacts that found every other taken, one after the other.
      const bool colour = stage >= first_colour_stage_ && stage + 1 < stage_end_.size();
      const std::size_t grain = stage < first_colour_stage_ ? 1 : kContactsPerChunk;
      largest = std::max(largest, reduce_blocks(
                                      last - first, grain, alone || shared_stage_[stage] == 0, 0.0,
                                      [&](std::size_t a, std::size_t b, double l) {
                                        return colour ? colour_tasks(first + a, first + b, l)
                                                      : tasks(first + a, first + b, l);
                                      },
                                      [](double a, double b) { return std::max(a, b); }));
      first = last;
    }
    return largest;
  }

 private:
  // An island cut into 2^depth parts; its groups of parts are numbered as in a binary heap (1:
  // the whole island, 2k and 2k + 1: the halves of k), from `first_group` in group_start_.
  struct PartedIsland {
    std::size_t root;
    int depth;
    std::size_t first_group;
  };
  /// Whether the last build holds for `contacts` (see build); if not, remembers what the next
  /// call compares with.
  bool holds_for(const ContactSet& contacts, std::span<const WarmStart> last_kept,
                 const BodyInertia& inertia, const IslandSplitting& splitting);
  void part(const ContactSet& contacts, const BodyInertia& inertia, std::span<const Vec2> positions,
            std::size_t parts);
  void colour(const ContactSet& contacts, const BodyInertia& inertia, std::size_t coloured_above);
  /// Which stages go to the threads (kSharedStageContacts), into shared_stage_.
  void choose_shared_stages();
  /// Places the next task's contacts, `task` in their order (not in order_), into its room in
  /// order_: level after level if they all have one point (see Visit), else as they are.
  void place_task(const ContactSet& contacts, std::span<const std::uint32_t> task);
  bool levelled(std::size_t t) const { return levels_of_[t].last > levels_of_[t].first; }
  /// Of a build whose contacts are to be stored in order: finds stored_at_ from order_, and makes
  /// order_ and the islands' contact indices those of the contacts once stored in order.
  void index_in_storage_order();

  ContactIslands islands_;
  // Of the last build: its contacts, and per body whether it was movable (which sleeping and
  // removal change); the contacts' pairs are those of the points kept after it.
  std::size_t built_contacts_ = 0;
  std::vector<char> movable_;
  IslandSplitting built_splitting_;
  std::vector<std::uint32_t> order_;      // contact indices, task after task
  std::vector<std::uint32_t> task_end_;   // per task: one past its last entry in order_
  std::vector<std::uint32_t> stage_end_;  // per stage: one past its last task
  std::size_t first_colour_stage_ = 0;
  std::vector<char> shared_stage_;  // per stage: 1 where its tasks go to the threads
  std::vector<PartedIsland> parted_;
  // Scratch of the build, per body: while parting, the part a body fell into, as halving bits;
  // while levelling, the level of its last contact. Per contact: while parting, the group of a
  // contact of a cut island; then a part's contacts, while they are placed.
  std::vector<std::uint32_t> body_scratch_;
  std::vector<std::uint32_t> contact_scratch_;
  std::uint32_t level_base_ = 0;            // while levelling: body levels up to this count as none
  std::vector<std::uint32_t> group_start_;  // per group: its first entry in order_
  std::vector<std::uint64_t> colours_;      // per body: the colours its contacts took, as bits
  std::vector<std::uint8_t> bucket_;        // per contact of a large island: its colour's bucket
  // Per task before the colours: its levels in level_end_, [first, last); none: not levelled.
  struct Levels {
    std::uint32_t first = 0, last = 0;
  };
  std::vector<Levels> levels_of_;
  std::vector<std::uint32_t> level_end_;  // per level: one past its last entry in order_
  // Of a build whose contacts are stored in order: per contact of their own order, its entry in
  // order_, which is then its index (order_ lists 0, 1, 2, ...); else empty. It and
  // contact_scratch_ hand one room to and fro: the scratch's between builds, the places' during.
  std::vector<std::uint32_t> stored_at_;
  bool stored_ = false;      // between store_in_order and restore_order
  std::vector<bool> moved_;  // per contact, scratch of store_in_order and restore_order
};

}  // namespace gp
