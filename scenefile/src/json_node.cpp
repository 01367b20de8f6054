#include "json_node.h"

#include <algorithm>
#include <cmath>

#include "edit_distance.h"
#include "particles/scenefile.h"

namespace particles::scenefile {

Node::Node(const nlohmann::json& value, std::string path, const std::string& file)
    : value_(&value), path_(std::move(path)), file_(&file) {}

void Node::fail(const std::string& problem) const {
  throw SceneError(*file_, path_, problem);
}

void Node::requireObject() const {
  if (!value_->is_object()) fail("must be an object {...}, got " + describe(*value_));
}

void Node::allowKeys(std::span<const std::string_view> known) const {
  requireObject();
  for (const auto& item : value_->items()) {
    const std::string& key = item.key();
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    const std::string suggestion = closestMatch(key, known);
    if (!suggestion.empty()) fail("unknown key '" + key + "'; did you mean '" + suggestion + "'?");
    fail("unknown key '" + key + "' (known keys: " + quotedList(known) + ")");
  }
}

std::optional<Node> Node::optional(std::string_view key) const {
  requireObject();
  const auto it = value_->find(key);
  if (it == value_->end()) return std::nullopt;
  return Node(*it, path_.empty() ? std::string(key) : path_ + "." + std::string(key), *file_);
}

Node Node::required(std::string_view key) const {
  std::optional<Node> child = optional(key);
  if (!child) fail("missing required key '" + std::string(key) + "'");
  return *child;
}

std::vector<Node> Node::elements() const {
  if (!value_->is_array()) fail("must be an array [...], got " + describe(*value_));
  std::vector<Node> out;
  out.reserve(value_->size());
  for (std::size_t i = 0; i < value_->size(); ++i)
    out.emplace_back((*value_)[i], path_ + "[" + std::to_string(i) + "]", *file_);
  return out;
}

std::string describe(const nlohmann::json& value) {
  constexpr std::size_t kMaxText = 40;
  switch (value.type()) {
    case nlohmann::json::value_t::object:
      return "an object";
    case nlohmann::json::value_t::array:
      return value.size() == 1 ? std::string("an array of 1 element")
                               : "an array of " + std::to_string(value.size()) + " elements";
    case nlohmann::json::value_t::string: {
      std::string text = value.dump();
      if (text.size() > kMaxText) text = text.substr(0, kMaxText) + "...\"";
      return "string " + text;
    }
    case nlohmann::json::value_t::number_float: {
      const double x = value.get<double>();
      if (std::isinf(x))
        return std::string("a number too large for a double (") + (x > 0 ? "" : "-") + "inf)";
      return formatDouble(x);
    }
    default:
      return value.dump();  // integers, true, false, null
  }
}

std::string quotedList(std::span<const std::string_view> names) {
  std::string out;
  for (std::string_view name : names) {
    if (!out.empty()) out += ", ";
    out += '\'';
    out += name;
    out += '\'';
  }
  return out;
}

}  // namespace particles::scenefile
