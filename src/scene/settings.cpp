#include "scene/settings.hpp"

#include <array>
#include <utility>

namespace gp {

namespace {
constexpr std::array<std::pair<IntegratorKind, std::string_view>, 3> kNames{{
    {IntegratorKind::SymplecticEuler, "symplectic_euler"},
    {IntegratorKind::VelocityVerlet, "velocity_verlet"},
    {IntegratorKind::RK4, "rk4"},
}};
}  // namespace

std::string_view integrator_name(IntegratorKind kind) {
  for (const auto& [k, name] : kNames) {
    if (k == kind) return name;
  }
  return "";
}

std::optional<IntegratorKind> integrator_from_name(std::string_view name) {
  for (const auto& [kind, n] : kNames) {
    if (n == name) return kind;
  }
  return std::nullopt;
}

}  // namespace gp
