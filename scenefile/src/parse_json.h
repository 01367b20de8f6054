// Text to JSON, strictly: syntax errors and duplicate keys are SceneErrors.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace particles::scenefile {

// "FILE: not valid JSON: parse error at line L, column C: ..." on bad syntax;
// "FILE: PATH: duplicate key 'radius'" when an object repeats a key (plain
// nlohmann would silently keep the last one); "FILE: PATH: must be a finite
// number, got 1e999 (too large for a double)" for a number that overflows.
nlohmann::json parseJson(std::string_view text, const std::string& file);

}  // namespace particles::scenefile
