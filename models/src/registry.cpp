#include "gamephysics/models/registry.hpp"

#include <algorithm>

// Including every model here guarantees that a program that asks for the registrations has them,
// whether or not it calls the models.
#include "gamephysics/models.hpp"

namespace gp::models {

namespace {
std::vector<Registration>& mutable_registrations() {
  static std::vector<Registration> list;
  return list;
}
}  // namespace

bool register_model(Registration registration) {
  mutable_registrations().push_back(std::move(registration));
  return true;
}

const std::vector<Registration>& registrations() {
  auto& list = mutable_registrations();
  std::sort(list.begin(), list.end(),
            [](const Registration& a, const Registration& b) { return a.id < b.id; });
  return list;
}

}  // namespace gp::models
