// A JSON value together with where it sits in the file, so that every check
// can report "FILE: JSON_PATH: problem".
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace particles::scenefile {

class Node {
 public:
  // `path` is "" for the top level, else e.g. "balls[3].radius".
  Node(const nlohmann::json& value, std::string path, const std::string& file);

  const nlohmann::json& value() const { return *value_; }
  const std::string& path() const { return path_; }
  const std::string& file() const { return *file_; }

  // Throws SceneError(file, path, problem).
  [[noreturn]] void fail(const std::string& problem) const;

  // Objects. allowKeys() also checks that this is an object, and rejects any
  // key not in `known` ("unknown key 'raduis'; did you mean 'radius'?").
  void requireObject() const;
  void allowKeys(std::span<const std::string_view> known) const;
  std::optional<Node> optional(std::string_view key) const;
  Node required(std::string_view key) const;  // "missing required key 'radius'"

  // Arrays: the elements, with paths "path[i]".
  std::vector<Node> elements() const;

 private:
  const nlohmann::json* value_;
  std::string path_;
  const std::string* file_;
};

// How a value reads in a message: 3.5, "string \"abc\"", "an object", ...
std::string describe(const nlohmann::json& value);

// A comma-separated list of quoted names: 'a', 'b', 'c'.
std::string quotedList(std::span<const std::string_view> names);

}  // namespace particles::scenefile
