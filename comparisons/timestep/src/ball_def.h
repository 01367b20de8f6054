// A ball for the catalogue's and the stress axes' scenes: SI units, the
// default disk inertia (BallDef), no material override.
#pragma once

#include "particles/scene.h"

namespace particles::timestep {

inline BallDef ball(Vec2 position, double radius, double mass, Vec2 velocity = Vec2::Zero(),
                    double spin = 0.0) {
  BallDef b;
  b.position = position;
  b.radius = radius;
  b.mass = mass;
  b.velocity = velocity;
  b.angularVelocity = spin;
  return b;
}

}  // namespace particles::timestep
