// The Box2D twin refills a world of at most two proxies instead of rebuilding
// it (reference/src/box2d_world.cpp). That is only allowed because it gives
// bit-identical results to a fresh world; these tests hold it to that over
// the suite's isolated cases, with a different case run before each one.
#include <gtest/gtest.h>

#include <cstring>

#include "particles/compare/case_generator.h"
#include "particles/reference/box2d_world.h"

namespace particles::compare {
namespace {

bool identical(const BallState& x, const BallState& y) {
  return std::memcmp(x.position.data(), y.position.data(), 2 * sizeof(double)) == 0 &&
         std::memcmp(x.velocity.data(), y.velocity.data(), 2 * sizeof(double)) == 0 &&
         std::memcmp(&x.angle, &y.angle, sizeof(double)) == 0 &&
         std::memcmp(&x.angularVelocity, &y.angularVelocity, sizeof(double)) == 0;
}

TEST(Box2DRefill, IsolatedCasesMatchAFreshWorldBitForBit) {
  std::optional<reference::Box2DWorld> reused;
  int compared = 0;
  for (int i = 0; i < 400; ++i) {
    for (Family f : {Family::NoSlip, Family::FrictionSliding, Family::Wall, Family::Smooth}) {
      const ImpactCase c = randomCase(f, 5, i);
      const auto settings = reference::Box2DSettings::forScene(c.scene);
      if (!reused) reused.emplace(c.scene, settings);
      reused->reset(c.scene);  // after whatever case ran last, ball-ball or ball-wall
      reference::Box2DWorld fresh(c.scene, settings);
      // Several steps, so that the broad phase moves its proxies too.
      for (int s = 0; s < 5; ++s) {
        reused->step();
        fresh.step();
        for (std::size_t b = 0; b < c.scene.balls.size(); ++b)
          ASSERT_TRUE(identical(reused->ball(b), fresh.ball(b))) << c.name << " step " << s;
      }
      ++compared;
    }
  }
  EXPECT_EQ(compared, 1600);
}

TEST(Box2DRefill, ALongTwoBallRunAfterAResetMatchesAFreshWorld) {
  // Two balls in a long run bounce through many contact begin/end cycles,
  // each of which moves proxies in the tree.
  ImpactCase c = randomCase(Family::NoSlip, 9, 1);
  c.scene.gravity = Vec2(0.0, -9.81);
  const auto settings = reference::Box2DSettings::forScene(c.scene);
  reference::Box2DWorld reused(randomCase(Family::Wall, 9, 2).scene, settings);
  reused.run(30);
  reused.reset(c.scene);
  reference::Box2DWorld fresh(c.scene, settings);
  for (int s = 0; s < 600; ++s) {
    reused.step();
    fresh.step();
    for (std::size_t b = 0; b < 2; ++b) ASSERT_TRUE(identical(reused.ball(b), fresh.ball(b))) << s;
  }
}

}  // namespace
}  // namespace particles::compare
