#include "engine/output/trajectory.hpp"

#include <array>
#include <cstdio>

namespace gp {

void write_number(std::ostream& out, double value) {
  // 17 significant digits identify every double; "%.17g" of one needs at most 24 characters.
  std::array<char, 32> text{};
  const int length = std::snprintf(text.data(), text.size(), "%.17g", value);
  out.write(text.data(), length);
}

void write_row(std::ostream& out, double t, std::string_view name, const BodyState& s) {
  write_number(out, t);
  out << ',' << name;
  for (double value : {s.position.x(), s.position.y(), s.angle, s.velocity.x(), s.velocity.y(),
                       s.angular_velocity}) {
    out << ',';
    write_number(out, value);
  }
  out << '\n';
}

TrajectoryCsv::TrajectoryCsv(std::ostream& out) : out_(out) {
  out_ << kTrajectoryHeader << '\n';
}

void TrajectoryCsv::write(double t, const Space& space) {
  for (BodyId body = 0; body < space.body_count(); ++body) {
    write_row(out_, t, space.name(body), space.state(body));
  }
}

}  // namespace gp
