#pragma once
// The names of a space's bodies, in one buffer: a std::string each would take 32 bytes before its
// first character, and most names are a few characters long.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace gp {

class BodyNames {
 public:
  /// Adds the name of the next body. Throws std::length_error past 4 GiB of names in all.
  void add(std::string_view name);
  std::size_t size() const { return ends_.size(); }
  std::string_view operator[](std::size_t body) const {
    const std::uint32_t begin = body == 0 ? 0 : ends_[body - 1];
    return std::string_view(characters_).substr(begin, ends_[body] - begin);
  }

 private:
  std::string characters_;
  std::vector<std::uint32_t> ends_;  // per body: where its name ends in characters_
};

}  // namespace gp
