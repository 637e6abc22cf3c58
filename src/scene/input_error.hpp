#pragma once
// The typed error for input that breaks an SRS data constraint or the scene format
// (FR:Verify-Physical_Constraints).

#include <stdexcept>
#include <string>

namespace gp {

/// Bad input: names where (e.g. "bodies[3].mass"), the rule broken, and the offending value.
class InputError : public std::runtime_error {
 public:
  InputError(std::string field, std::string rule, std::string value);

  const std::string& field() const { return field_; }
  const std::string& rule() const { return rule_; }
  const std::string& value() const { return value_; }

 private:
  std::string field_;
  std::string rule_;
  std::string value_;
};

}  // namespace gp
