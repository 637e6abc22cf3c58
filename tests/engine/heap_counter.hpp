#pragma once
// The test program's own account of its heap: heap_counter.cpp replaces the global operator new
// and delete, and adds what the engine's TrivialRooms hold (they grow by realloc, past operator
// new), so that a test can count what a step allocates or bound what a space holds.

#include <cstddef>

namespace gp::test {

/// Blocks operator new has handed out in this program so far, and rooms given new room.
long allocations();

/// Bytes in the blocks from operator new not deleted yet, as the allocator sized them, and in the
/// rooms.
std::size_t heap_in_use();

}  // namespace gp::test
