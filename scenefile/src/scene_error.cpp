#include <algorithm>

#include "particles/scenefile.h"

namespace particles {
namespace {

// Messages are one line whatever went into them.
std::string oneLine(std::string text) {
  std::replace_if(
      text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return text;
}

}  // namespace

SceneError::SceneError(const std::string& message) : std::runtime_error(oneLine(message)) {}

SceneError::SceneError(const std::string& file, const std::string& path, const std::string& problem)
    : SceneError(file + ": " + (path.empty() ? "top level" : path) + ": " + problem) {}

}  // namespace particles
