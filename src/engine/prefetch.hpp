#pragma once
// Cache lines asked for ahead of the stores that write them, where a loop writes memory in an
// order the hardware does not foresee: on two cores, a line the other core last wrote otherwise
// makes the store wait for a round trip between them (the bench's hand-over line: 0.1–13 µs).

#include <cstddef>
#include <cstdint>

#if defined(__x86_64__)
#include <cpuid.h>
#endif

namespace gp {

inline constexpr std::size_t kCacheLine = 64;

#if defined(__x86_64__)
/// Whether the processor has PREFETCHW (CPUID 8000_0001h, ECX bit 8).
inline const bool kHasPrefetchW = [] {
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  return __get_cpuid(0x80000001U, &eax, &ebx, &ecx, &edx) != 0 && (ecx & bit_PRFCHW) != 0;
}();
#endif

/// Asks for the cache line holding `p` to be brought to this core, held to be written.
inline void prefetch_for_writing(const void* p) {
#if defined(__x86_64__)
  // PREFETCHW: __builtin_prefetch(p, 1) gives it only where the whole build enables it
  // (-mprfchw), and otherwise a read prefetch, which leaves the line shared with the other core,
  // so that the store still waits on it.
  if (kHasPrefetchW) asm volatile("prefetchw %0" : : "m"(*static_cast<const char*>(p)));
#else
  __builtin_prefetch(p, 1, 3);
#endif
}

/// The same for every cache line of the `bytes` bytes from `first`.
inline void prefetch_for_writing(const void* first, std::size_t bytes) {
  const auto start = reinterpret_cast<std::uintptr_t>(first) & ~std::uintptr_t{kCacheLine - 1};
  const auto end = reinterpret_cast<std::uintptr_t>(first) + bytes;
  for (std::uintptr_t line = start; line < end; line += kCacheLine) {
    prefetch_for_writing(reinterpret_cast<const void*>(line));
  }
}

}  // namespace gp
