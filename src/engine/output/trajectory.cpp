#include "engine/output/trajectory.hpp"

#include <array>
#include <cstdio>

namespace gp {

namespace {

// 17 significant digits identify every double; "%.17g" of one needs at most 24 characters.
constexpr std::size_t kNumberSize = 32;

void put(std::ostream& out, double value) {
  std::array<char, kNumberSize> text{};
  const int length = std::snprintf(text.data(), text.size(), "%.17g", value);
  out.write(text.data(), length);
}

}  // namespace

TrajectoryCsv::TrajectoryCsv(std::ostream& out) : out_(out) {
  out_ << kTrajectoryHeader << '\n';
}

void TrajectoryCsv::write(double t, const Space& space) {
  for (BodyId body = 0; body < space.body_count(); ++body) {
    const BodyState s = space.state(body);
    put(out_, t);
    out_ << ',' << space.name(body);
    for (double value : {s.position.x(), s.position.y(), s.angle, s.velocity.x(), s.velocity.y(),
                         s.angular_velocity}) {
      out_ << ',';
      put(out_, value);
    }
    out_ << '\n';
  }
}

}  // namespace gp
