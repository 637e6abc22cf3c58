#include "engine/solver/contacts_in_fours.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace gp {

double solve_in_fours(FourContactsKernel kernel, const char* who, ContactSet& set,
                      std::span<const std::uint32_t> contacts, const BodyInertia& inertia,
                      MotionState& s) {
  if (kernel == nullptr) throw std::logic_error(std::string(who) + ": four lanes need AVX2");
  double largest = 0.0;
  for (std::size_t done = 0; done < contacts.size(); done += 4) {
    largest =
        std::max(largest, kernel(set, contacts.data() + done,
                                 std::min<std::size_t>(4, contacts.size() - done), inertia, s));
  }
  return largest;
}

}  // namespace gp
