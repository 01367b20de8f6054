// A SceneDef as a scene file (docs/scene-format.md), so that generated scenes
// (the stress run's broken cases) can be replayed by `particles run` and
// `particles compare`. loadScene() of the text gives back the same SceneDef:
// every number is written as its shortest round-trip decimal.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "particles/scene.h"

namespace particles {

// Every field is written explicitly (no reliance on defaults): the scene
// material, each ball's mass and resolved inertia, each wall, each force,
// dt, duration and the solver bounds. A no-slip friction is "infinite"; a
// force that never ends has no "end". The mutation is not written (scene
// files cannot set it).
nlohmann::json sceneJson(const SceneDef& scene);
// sceneJson as text, one-space indentation, ending with a newline.
std::string sceneText(const SceneDef& scene);

}  // namespace particles
