// Rejects scenes whose bodies already overlap at t = 0.
#pragma once

#include <string>
#include <vector>

#include "particles/scene.h"

namespace particles::scenefile {

// Overlap allowed at t = 0, relative to the radii sum (ball-ball) or the
// radius (ball-wall): rounding of "exactly touching", not penetration. The
// engine's position pass uses the same tolerance.
inline constexpr double kInitialOverlapTolerance = 1e-9;

// Throws SceneError naming the first offending pair (ball pairs in (i, j)
// order first, then balls against walls). wallNames[k] names scene.walls[k]
// in messages ("walls[2]", "box bottom wall"). Uses the engine's grid, so the
// cost grows with the number of touching pairs, not n^2.
void checkInitialOverlaps(const SceneDef& scene, const std::vector<std::string>& wallNames,
                          const std::string& file);

}  // namespace particles::scenefile
