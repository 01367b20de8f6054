// The velocities of every ball of a world, engine or Box2D twin alike (both
// have ballCount() and ball(i)).
#pragma once

#include <vector>

#include "particles/compare/outcome.h"

namespace particles::compare::detail {

template <typename W>
std::vector<BodyVelocity> velocitiesOf(const W& world) {
  std::vector<BodyVelocity> v;
  v.reserve(world.ballCount());
  for (std::size_t i = 0; i < world.ballCount(); ++i) {
    const BallState s = world.ball(i);
    v.push_back({s.velocity, s.angularVelocity});
  }
  return v;
}

}  // namespace particles::compare::detail
