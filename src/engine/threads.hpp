#pragma once
// Whether the step runs on one thread: the current task arena, or --threads 1 (a
// tbb::global_control), allows no more. The parallel parts then run as plain loops, without the
// cost of handing out tasks or of buffers that only threads need.

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

namespace gp {

inline bool one_thread() {
  return tbb::this_task_arena::max_concurrency() == 1 ||
         tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) == 1;
}

}  // namespace gp
