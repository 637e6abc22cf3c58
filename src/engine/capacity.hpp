#pragma once
// How the engine's per-step buffers grow: close to the largest count they have held, rather than
// up to twice it as a std::vector grows by itself, and seldom, so that a count creeping up step
// after step does not reallocate (and fragment the heap) at every new high.

#include <cstddef>
#include <vector>

namespace gp {

/// Makes room in `buffer` for `count` elements, and a quarter more when it must grow.
template <typename T>
void reserve_for(std::vector<T>& buffer, std::size_t count) {
  if (buffer.capacity() < count) buffer.reserve(count + count / 4);
}

/// Appends `value` to `buffer`, which grows by a quarter when full.
template <typename T>
void append(std::vector<T>& buffer, const T& value) {
  if (buffer.size() == buffer.capacity()) buffer.reserve(buffer.size() + buffer.size() / 4 + 1);
  buffer.push_back(value);
}

}  // namespace gp
