#pragma once
// How the engine's buffers grow: close to the largest count they have held, rather than up to
// twice it as a std::vector grows by itself. A buffer grows by an eighth, so that it holds about
// 6% more than it needs on average rather than a third (memory per body counts what is held), and
// a count creeping up step after step still reallocates only at every eighth more.

#include <cstddef>
#include <type_traits>
#include <vector>

namespace gp {

/// The room a buffer grown for `count` elements gets: an eighth more.
inline std::size_t grown_room(std::size_t count) {
  return count + count / 8;
}

/// Makes room in `buffer` for `count` elements, and an eighth more when it must grow.
template <typename T>
void reserve_for(std::vector<T>& buffer, std::size_t count) {
  if (buffer.capacity() < count) buffer.reserve(grown_room(count));
}

/// Appends `value` to `buffer`, which grows by an eighth when full.
template <typename T>
void append(std::vector<T>& buffer, const std::type_identity_t<T>& value) {
  reserve_for(buffer, buffer.size() + 1);
  buffer.push_back(value);
}

}  // namespace gp
