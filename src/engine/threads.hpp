#pragma once
// Whether the step runs on one thread: the current task arena, or --threads 1 (a
// tbb::global_control), allows no more. The parallel parts then run as plain loops, without the
// cost of handing out tasks or of buffers that only threads need.

#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

namespace gp {

inline bool one_thread() {
  return tbb::this_task_arena::max_concurrency() == 1 ||
         tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) == 1;
}

/// Calls work(first, last) over [0, count): once, a plain loop, when `alone` (too little work to
/// share out) or on one thread; else on the threads of the current task arena, in blocks of about
/// `grain`, in any order.
template <typename Work>
void for_blocks(std::size_t count, std::size_t grain, bool alone, const Work& work) {
  if (alone || one_thread()) {
    work(std::size_t{0}, count);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, grain),
                    [&](const tbb::blocked_range<std::size_t>& r) { work(r.begin(), r.end()); });
}

/// The same for work(first, last, value) → value, which carries `value` on over its blocks: the
/// blocks' values are joined by `join`, which must give the same whatever the order (a sum of
/// integers, a minimum) for the result not to depend on the number of threads.
template <typename Value, typename Work, typename Join>
Value reduce_blocks(std::size_t count, std::size_t grain, bool alone, Value identity,
                    const Work& work, const Join& join) {
  if (alone || one_thread()) return work(std::size_t{0}, count, identity);
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, count, grain), identity,
      [&](const tbb::blocked_range<std::size_t>& r, Value value) {
        return work(r.begin(), r.end(), value);
      },
      join);
}

}  // namespace gp
