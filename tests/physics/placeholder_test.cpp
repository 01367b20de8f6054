#include <gtest/gtest.h>

#include "particles/world.h"

TEST(Build, EngineLinks) {
  particles::SceneDef scene;
  scene.balls.push_back({});
  particles::World world(scene);
  world.step();
  EXPECT_EQ(world.stepIndex(), 1);
}
