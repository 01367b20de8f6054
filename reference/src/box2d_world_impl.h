// Box2DWorld's private state: the only place that holds Box2D objects. Shared
// by box2d_world.cpp (building, stepping) and box2d_inspect.cpp (reading back).
#pragma once

#include <box2d/box2d.h>

#include <optional>
#include <vector>

#include "particles/reference/box2d_world.h"

namespace particles::reference {

struct Box2DWorld::Impl {
  Box2DSettings settings;
  // Constructed in place by build(); reset() destroys and re-constructs it in
  // the same storage, which is what makes reuse identical to a fresh world.
  std::optional<b2World> world;
  std::vector<b2Body*> balls;            // scene ball order
  std::vector<b2Fixture*> wallFixtures;  // scene wall order, all on one static body
  std::vector<ForceDef> forces;          // the scene's, with pull targets as last set
  long long stepIndex = 0;
  Box2DLimitHits limitHits;

  void build(const SceneDef& scene);
  bool canRefill(const SceneDef& scene) const;
  void empty();
  void applyForces();
  void countLimitHits();
};

// Fixture user data: which ball or wall a fixture stands for. The body type
// tells the two apart (balls are dynamic, walls static).
inline int fixtureIndex(b2Fixture* fixture) {
  return static_cast<int>(fixture->GetUserData().pointer);
}

inline Vec2 toVec2(const b2Vec2& v) {
  return Vec2(v.x, v.y);
}
inline b2Vec2 toB2(const Vec2& v) {
  return b2Vec2(static_cast<float>(v.x()), static_cast<float>(v.y()));
}

}  // namespace particles::reference
