// SolverSettings::sweptWalls: continuous collision against walls.
#include <gtest/gtest.h>

#include <cmath>

#include "particles/swept_wall.h"
#include "particles/world.h"

namespace particles {
namespace {

// A ball of radius 0.5 at x = 0 moving at 2500 m/s (5 radii per 1 ms step)
// toward a wall at x = 2, e = 1, no gravity: its surface reaches the wall
// when the centre is at 1.5, after 1.5 / 2500 s = 0.6 ms, within the first
// step. Bounced elastically it is at 1.5 - 2500 * 0.4e-3 = 0.5 after the
// step, and after n steps at 1.5 - 2500 (n dt - 0.6e-3).
SceneDef fastBall(bool swept) {
  SceneDef s;
  s.contact = {1.0, 0.0};
  WallDef w;
  w.a = {2, -5};
  w.b = {2, 5};
  s.walls = {w};
  BallDef b;
  b.radius = 0.5;
  b.velocity = {2500, 0};
  s.balls = {b};
  s.dt = 1e-3;
  s.solver.sweptWalls = swept;
  return s;
}

TEST(SweptWalls, WithoutTheFlagAFastBallTunnels) {
  World w(fastBall(false));
  w.run(3);
  EXPECT_GT(w.ball(0).position.x(), 2.0);
}

TEST(SweptWalls, WithTheFlagItBouncesAtTheTimeOfImpact) {
  World w(fastBall(true));
  w.step();
  EXPECT_NEAR(w.ball(0).position.x(), 0.5, 1e-12);
  EXPECT_EQ(w.ball(0).velocity.x(), -2500.0);
  w.run(2);
  EXPECT_NEAR(w.ball(0).position.x(), 1.5 - 2500 * (3e-3 - 0.6e-3), 1e-9);
}

// Straight at a wall's round end: a ball at (0, 3) moving down at 10 m/s onto the end point
// (0, 0) of a vertical wall touches it when the centre is at y = 0.5, after
// 0.25 s; the normal then points straight down from the centre.
TEST(SweptWalls, RoundEndsAreSwept) {
  WallDef w;
  w.a = {0, 0};
  w.b = {0, -5};
  const auto hit = sweepAgainstWall({0, 3}, {0, -10}, 0.5, w, 1.0);
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->time, 0.25, 1e-15);
  EXPECT_NEAR(hit->normal.y(), -1.0, 1e-15);
  EXPECT_FALSE(sweepAgainstWall({0, 3}, {0, -10}, 0.5, w, 0.2).has_value());  // too short a step
  EXPECT_FALSE(sweepAgainstWall({0, 3}, {0, 10}, 0.5, w, 1.0).has_value());   // moving away
  EXPECT_FALSE(sweepAgainstWall({0.4, 0}, {1, 0}, 0.5, w, 1.0).has_value());  // already touching
}

// A slow ball (3 m/s, 0.003 m per step) from x = 0.0007 reaches the wall's
// contact x = 1.5 at t = (1.5 - 0.0007) / 3 = 0.49977 s, between steps.
// Exact motion: x(1 s) = 1.5 - 3 (1 - 0.49977) = -0.00069. The discrete step
// bounces it up to a step late (an error up to v dt = 3e-3 m, then the
// projection); the swept contact bounces it at the time of impact: exact to rounding.
TEST(SweptWalls, ASlowBallBouncesAtTheExactTime) {
  auto run = [](bool swept) {
    SceneDef s = fastBall(swept);
    s.balls[0].position = {0.0007, 0};
    s.balls[0].velocity = {3, 0};
    World w(s);
    w.run(1000);
    return w.ball(0).position.x();
  };
  const double exact = 1.5 - 3.0 * (1.0 - (1.5 - 0.0007) / 3.0);
  EXPECT_NEAR(run(true), exact, 1e-12);
  EXPECT_GT(std::fabs(run(false) - exact), 1e-4);
}

// Products that overflow (|v|^2 = inf, so the discriminant is inf - inf) must
// give no hit rather than a hit at time NaN, which would then move the ball
// by NaN.
TEST(SweptWalls, OverflowingProductsGiveNoNaNTime) {
  WallDef point;
  point.a = {1, 1};
  point.b = {1, 1};
  const auto hit = sweepAgainstWall({0, 0}, {1e200, 1e200}, 0.5, point, 1e-3);
  if (hit) {
    EXPECT_TRUE(std::isfinite(hit->time));
    EXPECT_GE(hit->time, 0.0);
    EXPECT_LE(hit->time, 1e-3);
  }
}

}  // namespace
}  // namespace particles
