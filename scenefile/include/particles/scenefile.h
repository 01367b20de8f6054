// Scene files: JSON in, SceneDef out. The format, its defaults and every
// check are documented in docs/scene-format.md. Everything that is wrong with
// a file is reported as a SceneError whose what() is one line,
//   FILE: JSON_PATH: what was wrong
// e.g. "scenes/bad.json: balls[3].radius: must be > 0, got -1".
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "particles/scene.h"
#include "particles/scene_output.h"

namespace particles {

class SceneError : public std::runtime_error {
 public:
  // A complete one-line message (newlines are replaced by spaces).
  explicit SceneError(const std::string& message);
  // "file: path: problem"; an empty path is the top level of the file.
  SceneError(const std::string& file, const std::string& path, const std::string& problem);
};

// Reads and validates a scene file. Throws SceneError ("FILE: cannot open",
// "FILE: not valid JSON: ...", "FILE: PATH: ...").
SceneDef loadScene(const std::filesystem::path& file);

// The same for text already in memory; fileName is used only in messages.
SceneDef parseScene(std::string_view text, const std::string& fileName);

// The loader's checks on the timing, shared with command-line overrides.
// `where` names the value in the message ("scene.json: dt", "--dt").
void checkTimeStep(double dt, const std::string& where);        // finite, > 0
void checkDuration(double duration, const std::string& where);  // finite, >= 0
// round(duration / dt) must fit in the engine's 64-bit step counter.
void checkStepCount(double duration, double dt, const std::string& where);

}  // namespace particles
