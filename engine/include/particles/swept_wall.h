// Continuous collision of a moving ball against a wall segment (time of
// impact), for SolverSettings::sweptWalls: a ball fast enough to cross a wall
// within one step is caught at the moment its surface reaches the wall.
#pragma once

#include <optional>

#include "particles/scene.h"

namespace particles {

struct SweptHit {
  double time = 0.0;        // s after the start of the step, in [0, dt]
  Vec2 normal{0.0, -1.0};   // unit, from the ball's centre to the wall at that time
};

// The first time in (0, dt] at which a ball of radius r at x moving with
// constant velocity v touches `wall` (the segment, with its round ends), if
// it is apart from the wall at the start. nullopt if it does not touch
// within the step or already touches.
std::optional<SweptHit> sweepAgainstWall(const Vec2& x, const Vec2& v, double r,
                                         const WallDef& wall, double dt);

}  // namespace particles
