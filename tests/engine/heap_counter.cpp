#include "heap_counter.hpp"

#include <malloc.h>

#include <cstdlib>
#include <new>

#include "engine/trivial_room.hpp"

namespace {

long allocations = 0;
std::size_t in_use = 0;

void* counted_allocation(std::size_t size) noexcept {
  void* p = std::malloc(size == 0 ? 1 : size);
  if (p != nullptr) {
    ++allocations;
    in_use += malloc_usable_size(p);
  }
  return p;
}

void counted_free(void* p) noexcept {
  if (p != nullptr) in_use -= malloc_usable_size(p);
  std::free(p);
}

}  // namespace

namespace gp::test {

long allocations() {
  return ::allocations + trivial_room_resizes();
}

std::size_t heap_in_use() {
  return in_use + trivial_room_bytes();
}

}  // namespace gp::test

// Every non-aligned form is replaced, so that each block is freed by the allocator that made it
// (AddressSanitizer checks that).
void* operator new(std::size_t size) {
  if (void* p = counted_allocation(size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  return operator new(size);
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  return counted_allocation(size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  return counted_allocation(size);
}
void operator delete(void* p) noexcept {
  counted_free(p);
}
void operator delete[](void* p) noexcept {
  counted_free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  counted_free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  counted_free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  counted_free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  counted_free(p);
}
