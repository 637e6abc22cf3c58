#include "scene/json_fields.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <sstream>

#include "scene/input_error.hpp"

namespace gp {

std::string shortened(const std::string& text, std::size_t length) {
  if (text.size() <= length) return text;
  return text.substr(0, length) + "...";
}

std::string describe(const nlohmann::json& value) {
  // A string from the command line (an override) may be invalid UTF-8, which dump() would throw
  // on: shown with U+FFFD in its place instead.
  return shortened(value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

std::string describe(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

std::string element_path(const std::string& array_path, std::size_t index) {
  return array_path + "[" + std::to_string(index) + "]";
}

template <>
double read<double>(const nlohmann::json& value, const std::string& path) {
  if (!value.is_number()) throw InputError(path, "must be a number", describe(value));
  return value.get<double>();
}

template <>
int read<int>(const nlohmann::json& value, const std::string& path) {
  using limits = std::numeric_limits<int>;
  const bool fits = value.is_number_unsigned()
                        ? value.get<std::uint64_t>() <= static_cast<std::uint64_t>(limits::max())
                        : value.is_number_integer() && value.get<std::int64_t>() >= limits::min() &&
                              value.get<std::int64_t>() <= limits::max();
  if (!fits) throw InputError(path, "must be an integer (32 bits)", describe(value));
  return value.get<int>();
}

template <>
bool read<bool>(const nlohmann::json& value, const std::string& path) {
  if (!value.is_boolean()) throw InputError(path, "must be true or false", describe(value));
  return value.get<bool>();
}

template <>
std::string read<std::string>(const nlohmann::json& value, const std::string& path) {
  if (!value.is_string()) throw InputError(path, "must be a string", describe(value));
  return value.get<std::string>();
}

template <>
Vec2 read<Vec2>(const nlohmann::json& value, const std::string& path) {
  if (!value.is_array() || value.size() != 2) {
    throw InputError(path, "must be an array of 2 numbers [x, y]", describe(value));
  }
  return {read<double>(value[0], element_path(path, 0)),
          read<double>(value[1], element_path(path, 1))};
}

const nlohmann::json& read_array(const nlohmann::json& value, const std::string& path) {
  if (!value.is_array()) throw InputError(path, "must be an array", describe(value));
  return value;
}

JsonObject::JsonObject(const nlohmann::json& value, std::string path)
    : value_(value), path_(std::move(path)) {
  if (!value.is_object()) {
    throw InputError(path_.empty() ? "(file)" : path_, "must be an object", describe(value));
  }
}

void JsonObject::allow_only(std::initializer_list<std::string_view> known) const {
  for (const auto& [key, value] : value_.items()) {
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    std::string list;
    for (std::string_view name : known) list.append(list.empty() ? "" : ", ").append(name);
    throw InputError(path(key), "is not a known field (known: " + list + ")", describe(value));
  }
}

std::string JsonObject::path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

const nlohmann::json& JsonObject::required(std::string_view key) const {
  const nlohmann::json* value = find(key);
  if (!value) throw InputError(path(key), "is required", "none");
  return *value;
}

const nlohmann::json* JsonObject::find(std::string_view key) const {
  const auto it = value_.find(key);
  return it == value_.end() ? nullptr : &*it;
}

}  // namespace gp
