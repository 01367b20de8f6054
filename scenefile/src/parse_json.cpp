#include "parse_json.h"

#include <set>
#include <vector>

#include "particles/scenefile.h"

namespace particles::scenefile {
namespace {

using Event = nlohmann::json::parse_event_t;

// Follows the parser through the document, so that problems found while
// parsing (a duplicate key, a number that overflows) can name a JSON path.
class PathTracker {
 public:
  explicit PathTracker(const std::string& file) : file_(file) {}

  // The parser's callback; throws SceneError on a duplicate key.
  void operator()(Event event, const nlohmann::json& parsed) {
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        stack_.push_back({event == Event::array_start, 0, {}, {}});
        break;
      case Event::key: {
        Frame& top = stack_.back();
        top.key = parsed.get<std::string>();
        if (!top.keys.insert(top.key).second)
          throw SceneError(file_, pathOf(stack_.size() - 1), "duplicate key '" + top.key + "'");
        break;
      }
      case Event::object_end:
      case Event::array_end:
        stack_.pop_back();
        finishedValue();
        break;
      case Event::value:
        finishedValue();
        break;
    }
  }

  // Path of the value being read.
  std::string currentPath() const { return pathOf(stack_.size()); }

 private:
  struct Frame {
    bool array;
    std::size_t index;  // arrays: element being read
    std::string key;    // objects: key being read
    std::set<std::string> keys;
  };

  void finishedValue() {
    if (!stack_.empty() && stack_.back().array) ++stack_.back().index;
  }

  // Path through the outermost `depth` open objects and arrays.
  std::string pathOf(std::size_t depth) const {
    std::string path;
    for (std::size_t i = 0; i < depth; ++i) {
      const Frame& f = stack_[i];
      if (f.array) {
        path += '[';
        path += std::to_string(f.index);
        path += ']';
      } else {
        if (!path.empty()) path += '.';
        path += f.key;
      }
    }
    return path;
  }

  const std::string& file_;
  std::vector<Frame> stack_;
};

}  // namespace

nlohmann::json parseJson(std::string_view text, const std::string& file) {
  PathTracker tracker(file);
  try {
    return nlohmann::json::parse(text, [&](int, Event event, nlohmann::json& parsed) {
      tracker(event, parsed);
      return true;
    });
  } catch (const nlohmann::json::parse_error& e) {
    // Drop nlohmann's "[json.exception.parse_error.101] " prefix.
    std::string message = e.what();
    if (const auto close = message.find("] ");
        message.starts_with("[json.") && close != message.npos)
      message.erase(0, close + 2);
    throw SceneError(file + ": not valid JSON: " + message);
  } catch (const nlohmann::json::out_of_range& e) {
    // 406: a number like 1e999 that overflows a double. Valid JSON, but not a
    // finite number, reported where it occurs.
    std::string message = e.what();
    const auto quote = message.find('\'');
    const std::string number = quote == message.npos
                                   ? message
                                   : message.substr(quote + 1, message.rfind('\'') - quote - 1);
    throw SceneError(file, tracker.currentPath(),
                     "must be a finite number, got " + number + " (too large for a double)");
  }
}

}  // namespace particles::scenefile
