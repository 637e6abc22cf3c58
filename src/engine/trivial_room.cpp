#include "engine/trivial_room.hpp"

#include <atomic>

namespace gp {

namespace {

// Rooms may be resized by spaces stepping on different threads at once.
std::atomic<std::size_t> bytes_held{0};
std::atomic<long> resizes{0};

}  // namespace

std::size_t trivial_room_bytes() {
  return bytes_held.load(std::memory_order_relaxed);
}

long trivial_room_resizes() {
  return resizes.load(std::memory_order_relaxed);
}

namespace detail {

void count_room(std::size_t old_bytes, std::size_t new_bytes) {
  bytes_held.fetch_add(new_bytes - old_bytes, std::memory_order_relaxed);
  if (new_bytes > 0) resizes.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace detail

}  // namespace gp
