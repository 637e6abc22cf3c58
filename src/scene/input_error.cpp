#include "scene/input_error.hpp"

namespace gp {

InputError::InputError(std::string field, std::string rule, std::string value)
    : std::runtime_error(
          std::string(field).append(": ").append(rule).append(", got ").append(value)),
      field_(std::move(field)),
      rule_(std::move(rule)),
      value_(std::move(value)) {}

}  // namespace gp
