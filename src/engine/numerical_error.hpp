#pragma once
// A run that produced a non-finite number stops with this error rather than go on silently.

#include <stdexcept>
#include <string>

namespace gp {

class NumericalError : public std::runtime_error {
 public:
  NumericalError(const std::string& body, double time)
      : std::runtime_error("body '" + body +
                           "' has a non-finite state at t = " + std::to_string(time) + " s"),
        body_(body),
        time_(time) {}
  const std::string& body() const { return body_; }
  double time() const { return time_; }

 private:
  std::string body_;
  double time_;
};

}  // namespace gp
