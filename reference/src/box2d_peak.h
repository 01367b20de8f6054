// How fast a ball may get during a scene, estimated without simulating: the
// start state plus what gravity, constant forces, torques and pulls can add
// over the scene's duration. Collisions can pass speed on to a lighter ball,
// which no cheap estimate bounds; Box2DWorld::limitHits() reports the clamps a
// run actually meets.
#pragma once

#include <cstddef>

#include "particles/scene.h"

namespace particles::reference {

struct Peak {
  double speed = 0.0;  // m/s
  double spin = 0.0;   // rad/s, from the start spin and torques (friction not included)
};

Peak estimatePeak(const SceneDef& scene, std::size_t ball);

}  // namespace particles::reference
