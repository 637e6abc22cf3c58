#pragma once
// The typed error of a scene the oracle cannot integrate as an ODE with isolated impacts.

#include <array>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace gp::verification {

/// The scene leaves the oracle's domain (scenes without persistent contact): bodies touching or
/// overlapping at the start, in resting contact after an impact, a Zeno sequence of impacts, or a
/// solver failure. The message says when, then what, naming the bodies.
/// A number for a message, to 6 significant digits ("1.5e-07", not std::to_string's "0.000000").
inline std::string message_number(double value) {
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), "%.6g", value);
  return text.data();
}

class OracleDomainError : public std::runtime_error {
 public:
  /// `problem` without the time, e.g. "bodies 'ball' and 'ground' are in resting contact".
  OracleDomainError(const std::string& problem, double time)
      : std::runtime_error("at t = " + seconds(time) + " s: " + problem), time_(time) {}

  /// s: when the oracle gave up.
  double time() const { return time_; }

 private:
  static std::string seconds(double t) {
    std::array<char, 32> text{};
    std::snprintf(text.data(), text.size(), "%.12g", t);
    return text.data();
  }

  double time_;
};

}  // namespace gp::verification
