#include "scene/json_document.hpp"

#include <set>
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

/// Where the parser is: one level per open object or array, enough to name a key's JSON path.
class PathTracker {
 public:
  /// The parser callback: follows the structure and rejects a key repeated within an object.
  bool operator()(int /*depth*/, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        count_array_element();
        if (levels_.size() == kMaxDepth) {
          throw InputError(levels_.empty() ? "(file)" : path(),
                           "must nest arrays and objects at most " + std::to_string(kMaxDepth) +
                               " deep (scenes need 7)",
                           "level " + std::to_string(kMaxDepth + 1));
        }
        levels_.push_back({event == Event::array_start, {}, {}, 0});
        break;
      case Event::object_end:
      case Event::array_end:
        levels_.pop_back();
        break;
      case Event::key: {
        Level& object = levels_.back();
        object.key = parsed.get<std::string>();
        if (!object.keys.insert(object.key).second) {
          throw InputError(path(), "is given twice in the same object", describe(parsed));
        }
        break;
      }
      case Event::value:
        count_array_element();
        break;
    }
    return true;
  }

 private:
  struct Level {
    bool array;
    std::set<std::string> keys;  // objects: the keys seen so far
    std::string key;             // objects: the current key
    std::size_t elements;        // arrays: the elements begun so far
  };

  void count_array_element() {
    if (!levels_.empty() && levels_.back().array) ++levels_.back().elements;
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

  std::vector<Level> levels_;
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
    return nlohmann::json::parse(text, PathTracker{});
  } catch (const nlohmann::json::parse_error& e) {
    throw syntax_error(e.what());
  } catch (const nlohmann::json::exception& e) {
    // e.g. "[json.exception.out_of_range.406] number overflow parsing '1e400'": no position.
    throw InputError("(file)", "must be valid JSON",
                     shortened(without_id(e.what()), kMessageLength));
  }
}

}  // namespace gp
