// Continuous collision of a moving ball against a wall segment (time of
// impact), for SolverSettings::sweptWalls: a ball fast enough to cross a wall
// within one step is caught at the moment its surface reaches the wall.
#pragma once

#include <optional>

#include "particles/scene.h"

namespace particles {

struct SweptHit {
  double time = 0.0;       // s after the start of the step, in [0, dt]
  Vec2 normal{0.0, -1.0};  // unit, from the ball's centre to the wall at that time
};

// The relative motion both sweeps reduce to: the earliest t in [0, dt] with
// |d + w t| = reach, for d outside that circle (|d| > reach) and closing
// (d.w < 0). nullopt otherwise, and also when the products overflow (a NaN
// is no time of impact). A ball against a wall's round end: d from the end
// to the centre, w the ball's velocity, reach its radius. Two balls: d and w
// of b relative to a, reach r_a + r_b.
std::optional<double> timeOfImpact(const Vec2& d, const Vec2& w, double reach, double dt);

// The first time in (0, dt] at which a ball of radius r at x moving with
// constant velocity v touches `wall` (the segment, with its round ends), if
// it is apart from the wall at the start. nullopt if it does not touch
// within the step or already touches.
std::optional<SweptHit> sweepAgainstWall(const Vec2& x, const Vec2& v, double r,
                                         const WallDef& wall, double dt);

}  // namespace particles
