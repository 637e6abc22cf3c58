#include "engine/scene/json_document.hpp"

#include <regex>
#include <set>
#include <vector>

#include "engine/input_error.hpp"

namespace gp {

namespace {

// The scene format nests 7 levels deep (root, bodies, a body, shapes, a shape, vertices, a
// vertex). Far deeper documents are refused while parsing: describing an offending value in an
// error message, like copying one, recurses once per level and would overflow the stack.
constexpr std::size_t kMaxDepth = 64;

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
          throw InputError(path(), "is given twice in the same object", parsed.dump());
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

}  // namespace

nlohmann::json parse_json_document(const std::string& text) {
  try {
    return nlohmann::json::parse(text, PathTracker{});
  } catch (const nlohmann::json::parse_error& e) {
    // nlohmann's message carries the position as "at line L, column C: what went wrong".
    static const std::regex position(R"(at (line \d+, column \d+): (.*)$)");
    std::smatch match;
    const std::string message = e.what();
    if (std::regex_search(message, match, position)) {
      throw InputError(match[1].str(), "must be valid JSON", match[2].str());
    }
    throw InputError("(file)", "must be valid JSON", message);
  } catch (const nlohmann::json::exception& e) {
    // e.g. "[json.exception.out_of_range.406] number overflow parsing '1e400'": no position.
    static const std::regex id(R"(^\[[^\]]*\] )");
    throw InputError("(file)", "must be valid JSON", std::regex_replace(e.what(), id, ""));
  }
}

}  // namespace gp
