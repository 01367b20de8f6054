// One-sided walls (WallDef::oneSided, what boxWalls makes): a ball touching
// the wall whose centre has crossed its line is pushed back to the wall's
// front (the left of a -> b), not on through; a two-sided segment pushes it
// out on the side its centre is on. Worked by hand below for the floor
// a = (0, 0), b = (10, 0): front normal perpLeft(b - a) / |b - a| = (0, 1),
// so a centre at height h (signed, < 0 behind) of a ball of radius r touches
// it when its distance to the segment is <= r, and then
//   one-sided: normal (0, -1) (ball to wall), overlap r - h;
//   two-sided: normal (0, sign(-h)), overlap r - |h|.
#include <gtest/gtest.h>

#include "particles/broad_phase.h"
#include "particles/world.h"

namespace particles {
namespace {

WallDef floorWall(bool oneSided) {
  WallDef w;
  w.a = {0.0, 0.0};
  w.b = {10.0, 0.0};
  w.oneSided = oneSided;
  return w;
}

TEST(OneSidedWall, CentreBehindTheLineLeavesByTheFront) {
  WallHit one, two;
  ASSERT_TRUE(touchWall({3.0, -0.2}, 0.5, floorWall(true), one));
  ASSERT_TRUE(touchWall({3.0, -0.2}, 0.5, floorWall(false), two));
  EXPECT_EQ(one.normal, Vec2(0.0, -1.0));
  EXPECT_NEAR(one.overlap, 0.7, 1e-15);  // r - h = 0.5 + 0.2
  EXPECT_EQ(two.normal, Vec2(0.0, 1.0));
  EXPECT_NEAR(two.overlap, 0.3, 1e-15);  // r - |h|
}

TEST(OneSidedWall, InFrontItIsTheTwoSidedWall) {
  WallHit one, two;
  ASSERT_TRUE(touchWall({3.0, 0.2}, 0.5, floorWall(true), one));
  ASSERT_TRUE(touchWall({3.0, 0.2}, 0.5, floorWall(false), two));
  EXPECT_EQ(one.normal, two.normal);
  EXPECT_EQ(one.overlap, two.overlap);
  EXPECT_EQ(one.normal, Vec2(0.0, -1.0));
  EXPECT_NEAR(one.overlap, 0.3, 1e-15);
  // Past the end, in front: the round end, as for a two-sided wall.
  ASSERT_TRUE(touchWall({10.3, 0.4}, 0.5, floorWall(true), one));
  EXPECT_NEAR(one.normal.x(), -0.6, 1e-15);  // (b - x) / |b - x| = (-0.3, -0.4) / 0.5
  EXPECT_NEAR(one.normal.y(), -0.8, 1e-15);
  EXPECT_NEAR(one.overlap, 0.0, 1e-15);
}

// The solid is as deep as the ball can touch: a ball wholly past the line
// (distance > r) no longer touches it, from either side.
TEST(OneSidedWall, ABallWhollyPastTheLineDoesNotTouchIt) {
  WallHit hit;
  EXPECT_FALSE(touchWall({3.0, -0.6}, 0.5, floorWall(true), hit));
  EXPECT_FALSE(touchWall({3.0, 0.6}, 0.5, floorWall(true), hit));
}

// boxWalls: counter-clockwise, each wall's front (its left) faces the box's
// centre, and all four are one-sided.
TEST(OneSidedWall, BoxWallsFaceIntoTheBox) {
  const Vec2 lo(-2.0, -1.0), hi(3.0, 4.0), centre = (lo + hi) / 2.0;
  for (const WallDef& w : boxWalls(lo, hi)) {
    EXPECT_TRUE(w.oneSided);
    const Vec2 front = perpLeft(w.b - w.a);
    EXPECT_GT(front.dot(centre - w.a), 0.0);
  }
}

SceneDef ballInBox(const Vec2& centre, bool oneSided) {
  SceneDef s;
  s.dt = 1.0 / 60.0;
  s.gravity = {0.0, 0.0};
  s.walls = boxWalls({0.0, 0.0}, {10.0, 10.0});
  for (WallDef& w : s.walls) w.oneSided = oneSided;
  BallDef b;
  b.position = centre;
  b.radius = 0.5;
  s.balls = {b};
  return s;
}

// A ball at rest with its centre 0.2 m below a box's floor (the small-scene
// path): the step's overlap removal lifts it by r - h = 0.7 m, to rest on the
// floor at y = r. With two-sided walls it drops to y = -r, out of the box.
TEST(OneSidedWall, SmallPathPutsABallBehindTheFloorBackInTheBox) {
  World one(ballInBox({5.0, -0.2}, true));
  one.step();
  EXPECT_NEAR(one.ball(0).position.y(), 0.5, 1e-12);
  EXPECT_EQ(one.ball(0).position.x(), 5.0);
  EXPECT_EQ(one.ball(0).velocity, Vec2(0.0, 0.0));
  World two(ballInBox({5.0, -0.2}, false));
  two.step();
  EXPECT_NEAR(two.ball(0).position.y(), -0.5, 1e-12);
}

// Behind both walls at a corner, within reach of their common end: each
// wall sends it to its front, and it ends in the corner, touching both.
TEST(OneSidedWall, SmallPathPutsABallOutsideACornerInTheCorner) {
  World w(ballInBox({-0.3, -0.2}, true));
  w.step();
  EXPECT_NEAR(w.ball(0).position.x(), 0.5, 1e-12);
  EXPECT_NEAR(w.ball(0).position.y(), 0.5, 1e-12);
}

}  // namespace
}  // namespace particles
