#pragma once
// Room for entries moved by their bytes that grows and shrinks in place where it can:
// by realloc, which remaps a large block rather than copying it, and without writing the room
// past what the caller fills, whose pages are then not touched. A page touched for the first time
// costs the kernel a fault (16 µs a 4 KiB page on the bench's machines, against 0.4 µs for a
// huge page), and a pile's first step makes tens of megabytes of contacts: growing a std::vector
// writes its whole room and copies what it held, each time it doubles.

#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

namespace gp {

/// The bytes every TrivialRoom holds together, and how many times one has been given new room:
/// what an account of the heap through operator new (the tests' heap counter) does not see.
std::size_t trivial_room_bytes();
long trivial_room_resizes();

namespace detail {
/// Records a room's change from `old_bytes` to `new_bytes`.
void count_room(std::size_t old_bytes, std::size_t new_bytes);
}  // namespace detail

/// `size()` entries of T, the first ones as the caller wrote them and the others undefined until
/// written. Copies copy the room whole. T holds no pointer into itself and needs no destructor, so
/// that its bytes moved elsewhere are the same entry: plain structs of numbers and Eigen's
/// fixed-size vectors (which are not trivially copyable only for their user-written copies).
template <typename T>
class TrivialRoom {
  static_assert(std::is_trivially_destructible_v<T> && std::is_standard_layout_v<T>);

 public:
  TrivialRoom() = default;
  TrivialRoom(const TrivialRoom& other) { *this = other; }
  TrivialRoom(TrivialRoom&& other) noexcept { swap(other); }
  TrivialRoom& operator=(const TrivialRoom& other) {
    if (this != &other) {
      resize(other.size_);
      if (size_ > 0) std::memcpy(static_cast<void*>(data_), other.data_, size_ * sizeof(T));
    }
    return *this;
  }
  TrivialRoom& operator=(TrivialRoom&& other) noexcept {
    TrivialRoom moved(std::move(other));
    swap(moved);
    return *this;
  }
  ~TrivialRoom() { resize(0); }

  std::size_t size() const { return size_; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }

  /// Room for `count` entries, the first min(count, size()) kept; 0 frees it. Throws
  /// std::bad_alloc, the room unchanged, when it cannot grow.
  void resize(std::size_t count) {
    if (count == size_) return;
    if (count == 0) {
      std::free(data_);
    } else {
      void* const moved = std::realloc(static_cast<void*>(data_), count * sizeof(T));
      if (moved == nullptr) throw std::bad_alloc();
      data_ = static_cast<T*>(moved);
    }
    detail::count_room(size_ * sizeof(T), count * sizeof(T));
    if (count == 0) data_ = nullptr;
    size_ = count;
  }

  void swap(TrivialRoom& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(size_, other.size_);
  }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace gp
