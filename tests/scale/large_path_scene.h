// Small scenes for the large-scene path's tests: a few balls put on the path
// by thresholds of 0 (docs/scale.md), and stacks of them on the floor.
#pragma once

#include "particles/scene.h"

namespace particles::test {

// An empty scene on the large path: time step dt (s), gravity g (m/s^2)
// straight down, e = 0 and mu = 0.5, and the box [lo, hi] (m).
inline SceneDef largePathScene(double dt, double g, Vec2 lo, Vec2 hi) {
  SceneDef s;
  s.dt = dt;
  s.gravity = {0.0, -g};
  s.contact = {0.0, 0.5};
  s.walls = boxWalls(lo, hi);
  s.solver.scaleThreshold = 0;
  s.solver.scaleThresholdUnderGravity = 0;
  return s;
}

// Appends `count` balls of radius r (m) and 1 kg, at rest, stacked at x (m)
// on the floor y = 0, each touching the next.
inline void addStack(SceneDef& s, double x, int count, double r) {
  for (int k = 0; k < count; ++k) {
    BallDef b;
    b.position = {x, (1.0 + 2.0 * k) * r};
    b.radius = r;
    b.mass = 1.0;
    s.balls.push_back(b);
  }
}

}  // namespace particles::test
