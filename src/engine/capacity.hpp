#pragma once
// How the engine's buffers grow: close to the largest count they have held, rather than up to
// twice it as a std::vector grows by itself. A per-step buffer grows seldom, so that a count
// creeping up step after step does not reallocate (and fragment the heap) at every new high; an
// array per body or shape grows by a quarter, so that it holds an eighth more than its bodies on
// average rather than a third.

#include <cstddef>
#include <type_traits>
#include <vector>

namespace gp {

/// Makes room in `buffer` for `count` elements, and a quarter more when it must grow.
template <typename T>
void reserve_for(std::vector<T>& buffer, std::size_t count) {
  if (buffer.capacity() < count) buffer.reserve(count + count / 4);
}

/// Appends `value` to `buffer`, which grows by a quarter when full.
template <typename T>
void append(std::vector<T>& buffer, const std::type_identity_t<T>& value) {
  if (buffer.size() == buffer.capacity()) buffer.reserve(buffer.size() + buffer.size() / 4 + 1);
  buffer.push_back(value);
}

}  // namespace gp
