#pragma once
// Typed, path-aware reading of the JSON document of a scene: every wrong type, missing field and
// unknown field becomes an InputError naming its JSON path, e.g. "bodies[0].shapes[1].radius"
// (FR:Verify-Physical_Constraints).

#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "gamephysics/models/types.hpp"

namespace gp {

/// Text as it appears in error messages: cut to `length` characters, with "...", when longer. The
/// default shows a vector or a short object in full and keeps a message on one line.
std::string shortened(const std::string& text, std::size_t length = 100);
/// A JSON value as it appears in error messages: its JSON text, cut short when long.
std::string describe(const nlohmann::json& value);
/// A number as it appears in error messages: 17 significant digits, so that it round-trips.
std::string describe(double value);

/// "bodies" + 3 → "bodies[3]".
std::string element_path(const std::string& array_path, std::size_t index);

/// `value` as a T, or InputError naming `path` ("must be a number", "must be an integer", "must be
/// a string", "must be an array of 2 numbers [x, y]", "must be true or false"). T is double, int,
/// bool, std::string or Vec2.
template <typename T>
T read(const nlohmann::json& value, const std::string& path);
template <>
double read<double>(const nlohmann::json& value, const std::string& path);
template <>
int read<int>(const nlohmann::json& value, const std::string& path);
template <>
bool read<bool>(const nlohmann::json& value, const std::string& path);
template <>
std::string read<std::string>(const nlohmann::json& value, const std::string& path);
template <>
Vec2 read<Vec2>(const nlohmann::json& value, const std::string& path);

/// `value` itself when it is an array, else InputError naming `path`.
const nlohmann::json& read_array(const nlohmann::json& value, const std::string& path);

/// An object of the scene file and its path, read field by field.
class JsonObject {
 public:
  /// Throws InputError naming `path` ("(file)" for the root) when `value` is not an object.
  JsonObject(const nlohmann::json& value, std::string path);

  /// Throws InputError naming the first field not in `known`: a misspelt optional field would
  /// otherwise be ignored and its default used without a word.
  void allow_only(std::initializer_list<std::string_view> known) const;

  /// The path of field `key`: "dt" at the root, "bodies[2].mass" below it.
  std::string path(std::string_view key) const;

  /// The field `key`, or InputError "is required" when it is absent.
  const nlohmann::json& required(std::string_view key) const;
  /// The field `key`, or nullptr when it is absent.
  const nlohmann::json* find(std::string_view key) const;

  template <typename T>
  T get(std::string_view key) const {
    return read<T>(required(key), path(key));
  }
  template <typename T>
  std::optional<T> get_optional(std::string_view key) const {
    const nlohmann::json* value = find(key);
    if (!value) return std::nullopt;
    return read<T>(*value, path(key));
  }
  template <typename T>
  T get_or(std::string_view key, T fallback) const {
    return get_optional<T>(key).value_or(std::move(fallback));
  }

 private:
  const nlohmann::json& value_;
  std::string path_;  // empty at the root
};

}  // namespace gp
