// The large-scene path against a ball fast enough to cross a box wall's line
// within one step, before it has a row with the wall: the 100,000 pile
// threw balls out through the side walls this way (docs/scale.md, "Walls
// with a side").
//
// Box [0, 10]^2, no gravity, e = 0.5, a ball of radius r = 0.5 at x = 0.8
// moving at u = 60 m/s towards the left wall, dt = 1/60 s. Its gap to the
// wall, 0.3 m, is more than the rows' margin (0.2 r = 0.1 m), so step 1 has
// no wall row and the ball moves u dt = 1 m, to x = -0.2: its centre is past
// the wall's line, within r of it.
// Step 2, one-sided wall (boxWalls): the ball touches the wall from behind,
// normal (-1, 0) towards the wall, and is approaching at u: the row bounces
// it to vx = +e u = 30 m/s; it moves to -0.2 + 0.5 = 0.3 and the overlap
// removal puts it at x = r = 0.5.
// Step 2, two-sided wall: it touches the wall on its far side, normal (1, 0),
// and is leaving along it: no impulse; it moves on to -0.2 - u dt = -1.2,
// out of the box, still at -60 m/s.
#include <gtest/gtest.h>

#include "large_path_scene.h"
#include "particles/world.h"

namespace particles {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kSpeed = 60.0;  // m/s
constexpr double kE = 0.5;

SceneDef fastBallAtTheLeftWall(bool oneSided) {
  SceneDef s = test::largePathScene(kDt, 0.0, {0.0, 0.0}, {10.0, 10.0});
  s.contact = {kE, 0.5};
  for (WallDef& w : s.walls) w.oneSided = oneSided;
  BallDef b;
  b.position = {0.8, 5.0};
  b.velocity = {-kSpeed, 0.0};
  b.radius = 0.5;
  s.balls = {b};
  return s;
}

TEST(ScaleWallSide, ABallThatCrossedABoxWallComesBackIn) {
  World w(fastBallAtTheLeftWall(true));
  w.step();
  EXPECT_NEAR(w.ball(0).position.x(), -0.2, 1e-12);  // crossed: no row yet
  w.step();
  EXPECT_NEAR(w.ball(0).position.x(), 0.5, 1e-12);
  EXPECT_NEAR(w.ball(0).velocity.x(), kE * kSpeed, 1e-12);
  EXPECT_NEAR(w.ball(0).velocity.y(), 0.0, 1e-12);
  EXPECT_NEAR(w.ball(0).angularVelocity, 0.0, 1e-12);  // head-on: no friction
}

TEST(ScaleWallSide, ATwoSidedWallLetsItOut) {
  World w(fastBallAtTheLeftWall(false));
  w.run(2);
  EXPECT_NEAR(w.ball(0).position.x(), -1.2, 1e-12);
  EXPECT_EQ(w.ball(0).velocity.x(), -kSpeed);
}

// With one-sided walls the ball stays in the box however long it bounces:
// from step 2 on, its centre ends every step at least r from both walls (up
// to the overlap removal's tolerance, 1e-9 of the reach).
TEST(ScaleWallSide, TheBallStaysInTheBox) {
  World w(fastBallAtTheLeftWall(true));
  w.step();
  for (int k = 1; k < 600; ++k) {
    w.step();
    const double x = w.ball(0).position.x();
    ASSERT_GE(x, 0.5 - 1e-9) << "after step " << k + 1;
    ASSERT_LE(x, 9.5 + 1e-9) << "after step " << k + 1;
  }
}

}  // namespace
}  // namespace particles
