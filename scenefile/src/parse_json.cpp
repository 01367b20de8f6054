#include "parse_json.h"

#include <set>
#include <vector>

#include "particles/scenefile.h"

namespace particles::scenefile {
namespace {

using Json = nlohmann::json;

// A first, DOM-less pass over the text that follows the parser through the
// document, so that problems found while parsing (a duplicate key, a number
// that overflows, a syntax error) can name a JSON path. (A parse callback
// could do the same in one pass, but nlohmann's callback parser rescans the
// enclosing array after every element: quadratic, minutes for 10^5 balls.)
class PathTracker final : public nlohmann::json_sax<Json> {
 public:
  explicit PathTracker(const std::string& file) : file_(file) {}

  bool null() override { return finishedValue(); }
  bool boolean(bool) override { return finishedValue(); }
  bool number_integer(number_integer_t) override { return finishedValue(); }
  bool number_unsigned(number_unsigned_t) override { return finishedValue(); }
  bool number_float(number_float_t, const string_t&) override { return finishedValue(); }
  bool string(string_t&) override { return finishedValue(); }
  bool binary(binary_t&) override { return finishedValue(); }
  bool start_object(std::size_t) override { return open(false); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  // Throws SceneError on a duplicate key.
  bool key(string_t& key) override {
    Frame& top = stack_.back();
    top.key = key;
    if (!top.keys.insert(top.key).second)
      throw SceneError(file_, pathOf(stack_.size() - 1), "duplicate key '" + top.key + "'");
    return true;
  }

  bool parse_error(std::size_t, const std::string&, const Json::exception& e) override {
    overflow_ = dynamic_cast<const Json::out_of_range*>(&e) != nullptr;
    error_ = e.what();
    errorPath_ = pathOf(stack_.size());  // the value being read
    return false;
  }

  // The SceneError for the parser's error, if there was one.
  void throwIfFailed() const {
    if (error_.empty()) return;
    std::string message = error_;
    if (overflow_) {
      // 406: a number like 1e999 that overflows a double. Valid JSON, but not
      // a finite number, reported where it occurs.
      const auto quote = message.find('\'');
      const std::string number = quote == message.npos
                                     ? message
                                     : message.substr(quote + 1, message.rfind('\'') - quote - 1);
      throw SceneError(file_, errorPath_,
                       "must be a finite number, got " + number + " (too large for a double)");
    }
    // Drop nlohmann's "[json.exception.parse_error.101] " prefix.
    if (const auto close = message.find("] ");
        message.starts_with("[json.") && close != message.npos)
      message.erase(0, close + 2);
    throw SceneError(file_ + ": not valid JSON: " + message);
  }

 private:
  struct Frame {
    bool array;
    std::size_t index;  // arrays: element being read
    std::string key;    // objects: key being read
    std::set<std::string> keys;
  };

  bool open(bool array) {
    stack_.push_back({array, 0, {}, {}});
    return true;
  }

  bool close() {
    stack_.pop_back();
    return finishedValue();
  }

  bool finishedValue() {
    if (!stack_.empty() && stack_.back().array) ++stack_.back().index;
    return true;
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
  std::string error_, errorPath_;
  bool overflow_ = false;
};

}  // namespace

nlohmann::json parseJson(std::string_view text, const std::string& file) {
  PathTracker tracker(file);
  Json::sax_parse(text, &tracker);
  tracker.throwIfFailed();
  // Known valid now; parsed without a callback, in linear time.
  return Json::parse(text);
}

}  // namespace particles::scenefile
