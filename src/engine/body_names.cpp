#include "engine/body_names.hpp"

#include <limits>
#include <stdexcept>

#include "engine/capacity.hpp"

namespace gp {

void BodyNames::add(std::string_view name) {
  const std::size_t end = characters_.size() + name.size();
  if (end > std::numeric_limits<std::uint32_t>::max()) {
    throw std::length_error("BodyNames::add: more than 4 GiB of body names");
  }
  // A quarter more when it must grow, as the other arrays per body (a string would double).
  if (characters_.capacity() < end) characters_.reserve(end + end / 4);
  characters_ += name;
  append(ends_, static_cast<std::uint32_t>(end));
}

}  // namespace gp
