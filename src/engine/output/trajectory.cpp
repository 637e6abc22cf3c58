#include "engine/output/trajectory.hpp"

#include <array>
#include <charconv>

namespace gp {

namespace {

// 17 significant digits identify every double; one needs at most 24 characters.
constexpr std::size_t kNumberChars = 24;

// Writes `value` at `first` as printf's "%.17g" would, and returns the end. std::to_chars with
// a precision is defined as printf with it, and takes a tenth of its time: a trajectory written
// at every step of a 210-box pyramid cost twice the simulation through snprintf.
char* put_number(char* first, double value) {
  return std::to_chars(first, first + kNumberChars, value, std::chars_format::general, 17).ptr;
}

}  // namespace

void write_number(std::ostream& out, double value) {
  std::array<char, kNumberChars> text{};
  out.write(text.data(), put_number(text.data(), value) - text.data());
}

void write_row(std::ostream& out, double t, std::string_view name, const BodyState& s) {
  // The numbers after the name, each after a comma, and the line's end, written at once.
  std::array<char, 6 * (kNumberChars + 1) + 1> text{};
  write_number(out, t);
  out.put(',');
  out.write(name.data(), static_cast<std::streamsize>(name.size()));
  char* end = text.data();
  for (double value : {s.position.x(), s.position.y(), s.angle, s.velocity.x(), s.velocity.y(),
                       s.angular_velocity}) {
    *end++ = ',';
    end = put_number(end, value);
  }
  *end++ = '\n';
  out.write(text.data(), end - text.data());
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
