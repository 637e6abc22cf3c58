#include "scene/json_document.hpp"

#include <set>
#include <utility>
#include <vector>

#include "scene/input_error.hpp"
#include "scene/json_fields.hpp"

namespace gp {

namespace {

// The scene format nests 7 levels deep (root, bodies, a body, shapes, a shape, vertices, a
// vertex). Far deeper documents are refused while parsing: describing an offending value in an
// error message, like copying one, recurses once per level and would overflow the stack.
constexpr std::size_t kMaxDepth = 64;
// nlohmann's messages quote the last token read, which may be the rest of the file.
constexpr std::size_t kMessageLength = 200;

/// Builds the document from nlohmann's SAX events while following where the parser is, one level
/// per open object or array, enough to name a key's JSON path. Not nlohmann's parser callback:
/// that one searches the parent's elements at every closing bracket, quadratic in the number of
/// bodies (70 % of loading a 22,000-body scene).
class DocumentBuilder {
 public:
  nlohmann::json take() { return std::move(root_); }

  bool null() { return add(nullptr); }
  bool boolean(bool value) { return add(value); }
  bool number_integer(nlohmann::json::number_integer_t value) { return add(value); }
  bool number_unsigned(nlohmann::json::number_unsigned_t value) { return add(value); }
  bool number_float(nlohmann::json::number_float_t value, const std::string& /*text*/) {
    return add(value);
  }
  bool string(std::string& value) { return add(std::move(value)); }
  bool binary(nlohmann::json::binary_t& value) { return add(std::move(value)); }

  bool start_object(std::size_t /*elements*/) { return open(nlohmann::json::object(), false); }
  bool start_array(std::size_t /*elements*/) { return open(nlohmann::json::array(), true); }
  bool end_object() { return end_array(); }
  bool end_array() {
    levels_.pop_back();
    return true;
  }

  /// Rejects a key repeated within an object.
  bool key(std::string& key) {
    Level& object = levels_.back();
    object.key = key;
    if (!object.keys.insert(key).second) {
      throw InputError(path(), "is given twice in the same object", describe(nlohmann::json(key)));
    }
    member_ = &(*object.value)[key];
    return true;
  }

  /// Throws nlohmann's exception, of its own type (parse_error, out_of_range).
  template <class Exception>
  bool parse_error(std::size_t /*position*/, const std::string& /*token*/, const Exception& e) {
    throw e;
  }

 private:
  struct Level {
    nlohmann::json* value;
    bool array;
    std::set<std::string> keys;  // objects: the keys seen so far
    std::string key;             // objects: the current key
    std::size_t elements;        // arrays: the elements begun so far
  };

  /// Puts a value where the parser is: the root, the end of an array or the current key's member.
  template <class Value>
  nlohmann::json* place(Value&& value) {
    if (levels_.empty()) {
      root_ = std::forward<Value>(value);
      return &root_;
    }
    Level& level = levels_.back();
    if (level.array) {
      ++level.elements;
      level.value->push_back(std::forward<Value>(value));
      return &level.value->back();
    }
    *member_ = std::forward<Value>(value);
    return member_;
  }

  template <class Value>
  bool add(Value&& value) {
    place(nlohmann::json(std::forward<Value>(value)));
    return true;
  }

  bool open(nlohmann::json empty, bool array) {
    if (levels_.size() == kMaxDepth) {
      if (!levels_.empty() && levels_.back().array) ++levels_.back().elements;
      throw InputError(levels_.empty() ? "(file)" : path(),
                       "must nest arrays and objects at most " + std::to_string(kMaxDepth) +
                           " deep (scenes need 7)",
                       "level " + std::to_string(kMaxDepth + 1));
    }
    nlohmann::json* value = place(std::move(empty));
    levels_.push_back({value, array, {}, {}, 0});
    return true;
  }

  /// "bodies[2].mass": the path of the current key.
  std::string path() const {
    std::string result;
    for (const Level& level : levels_) {
      if (level.array) {
        result += "[" + std::to_string(level.elements - 1) + "]";
      } else {
        result += (result.empty() ? "" : ".") + level.key;
      }
    }
    return result;
  }

  nlohmann::json root_;
  std::vector<Level> levels_;
  nlohmann::json* member_ = nullptr;  // the member of the current key, in the innermost object
};

/// nlohmann's message less its "[json.exception.parse_error.101] " prefix.
std::string without_id(const std::string& message) {
  const std::size_t end = message.find("] ");
  return message.starts_with('[') && end != std::string::npos ? message.substr(end + 2) : message;
}

/// The error for nlohmann's parse_error, whose message reads "... at line L, column C: what went
/// wrong; last read: '<token>'". Found with plain searches: std::regex recursed once per character
/// of the message and overflowed the stack on a 22 kB token (verification/fuzz/crashes/).
InputError syntax_error(const std::string& message) {
  const std::size_t at = message.find(" at line ");
  const std::size_t colon = at == std::string::npos ? at : message.find(": ", at);
  if (colon == std::string::npos) {
    return InputError("(file)", "must be valid JSON",
                      shortened(without_id(message), kMessageLength));
  }
  const std::size_t line = at + std::string_view(" at ").size();
  return InputError(message.substr(line, colon - line), "must be valid JSON",
                    shortened(message.substr(colon + 2), kMessageLength));
}

}  // namespace

nlohmann::json parse_json_document(const std::string& text) {
  try {
    DocumentBuilder builder;
    nlohmann::json::sax_parse(text, &builder);
    return builder.take();
  } catch (const nlohmann::json::parse_error& e) {
    throw syntax_error(e.what());
  } catch (const nlohmann::json::exception& e) {
    // e.g. "[json.exception.out_of_range.406] number overflow parsing '1e400'": no position.
    throw InputError("(file)", "must be valid JSON",
                     shortened(without_id(e.what()), kMessageLength));
  }
}

}  // namespace gp
