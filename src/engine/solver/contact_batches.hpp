#pragma once
// The order in which the contact passes visit a step's contacts, and which of them may be solved
// side by side on several threads. Each island is solved on its own, in the contacts' order, as
// one thread would; an island of more contacts than Settings::coloured_island_contacts (when
// set) is graph-coloured instead, so that its contacts are solved colour after colour, the contacts
// of a colour side by side. The order depends on the contacts alone, never on the number of
// threads, so a step gives the same result to the bit on any number of them.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "engine/solver/contact_islands.hpp"
#include "engine/threads.hpp"

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

class ContactBatches {
 public:
  /// Contacts of a colour a thread takes at a time.
  static constexpr std::size_t kContactsPerChunk = 128;

  /// Groups `contacts` into stages of tasks: the islands of at most `coloured_above` contacts
  /// first (all of them when it is 0), one task each, then each colour of the larger islands, one
  /// task per contact. No two tasks of a stage share a body that the solver moves. Reuses its
  /// arrays' room.
  void build(const ContactSet& contacts, const BodyInertia& inertia, std::size_t coloured_above);

  /// The islands of the contacts build was given.
  const ContactIslands& islands() const { return islands_; }

  /// The largest value `solve(contact index)` returns over the contacts: stage after stage, the
  /// tasks of a stage on the threads the current task arena allows, a task's contacts in order.
  template <typename Solve>
  double run(const Solve& solve) const {
    const auto tasks = [&](std::size_t first, std::size_t last, double largest) {
      for (std::uint32_t e = first == 0 ? 0 : task_end_[first - 1]; e < task_end_[last - 1]; ++e)
        largest = std::max(largest, solve(order_[e]));
      return largest;
    };
    const bool alone = one_thread();
    double largest = 0.0;
    std::size_t first = 0;
    for (std::size_t stage = 0; stage < stage_end_.size(); ++stage) {
      const std::uint32_t last = stage_end_[stage];
      if (first == last) continue;
      // An island is a task of its own; a colour's contacts, each a task of tens of
      // nanoseconds, are handed out by the hundred, as each hand-out costs about a microsecond.
      const std::size_t grain = stage == 0 ? 1 : kContactsPerChunk;
      largest =
          alone ? tasks(first, last, largest)
                : std::max(largest, tbb::parallel_reduce(
                                        tbb::blocked_range<std::size_t>(first, last, grain), 0.0,
                                        [&](const tbb::blocked_range<std::size_t>& r, double l) {
                                          return tasks(r.begin(), r.end(), l);
                                        },
                                        [](double a, double b) { return std::max(a, b); }));
      first = last;
    }
    return largest;
  }

 private:
  ContactIslands islands_;
  std::vector<std::uint32_t> order_;      // contact indices, task after task
  std::vector<std::uint32_t> task_end_;   // per task: one past its last entry in order_
  std::vector<std::uint32_t> stage_end_;  // per stage: one past its last task
  std::vector<std::uint64_t> colours_;    // per body: the colours its contacts took, as bits
  std::vector<std::uint8_t> colour_;      // per contact of a large island: its colour
};

}  // namespace gp
