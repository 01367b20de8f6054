// Shock propagation in the large-scene path's overlap removal
// (SolverSettings::scaleShockPropagation, docs/scale.md), against the closed
// form of a two-ball stack on a floor.
//
// Ball 0 rests on the floor (y = r), ball 1 sits on it overlapping by d.
// One pass handles the rows in key order: the pair (0, 1), then ball 0 and
// the floor. The pair's overlap is shared with ball 0 (the lower) weighted
// 1 - k: ball 0 moves down d (1 - k) / (2 - k), ball 1 up d / (2 - k); the
// floor then lifts ball 0 back to y = r, which leaves the pair overlapping
// by d q, q = (1 - k) / (2 - k). After P passes: d q^P, ball 0 at y = r,
// ball 1 at y = 3 r - d q^P. k = 0 is the inverse-mass share (q = 1/2);
// k = 1 clears the stack in one pass.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "particles/world.h"

namespace particles {
namespace {

constexpr double kRadius = 0.5;    // m
constexpr double kOverlap = 0.01;  // m, d

BallDef restingBall(double y) {
  BallDef b;
  b.position = {0.0, y};
  b.radius = kRadius;
  b.mass = 1.0;
  return b;
}

// Two balls alone (no walls) on the large-scene path, one overlap-removal
// pass.
SceneDef pair(const BallDef& first, const BallDef& second, Vec2 gravity, double shock) {
  SceneDef s;
  s.dt = 1e-3;
  s.gravity = gravity;
  s.contact = {0.0, 0.0};
  s.balls = {first, second};
  s.solver.scaleThreshold = 0;
  s.solver.scaleThresholdUnderGravity = 0;
  s.solver.scalePositionPasses = 1;
  s.solver.scaleShockPropagation = shock;
  return s;
}

// The stack on the floor under a gravity so weak (1e-9 m/s^2) that the
// velocities it brings move nothing within the tolerances below: only its
// direction acts.
SceneDef stack(double shock, int passes) {
  SceneDef s =
      pair(restingBall(kRadius), restingBall(3.0 * kRadius - kOverlap), {0.0, -1e-9}, shock);
  s.contact = {0.0, 0.5};
  s.walls = boxWalls({-10.0, 0.0}, {10.0, 10.0});
  s.solver.scalePositionPasses = passes;
  return s;
}

TEST(ScaleShock, StackOverlapShrinksByTheClosedFormRatioPerPass) {
  for (const double k : {0.0, 0.3, 0.7}) {
    for (const int passes : {1, 2, 4}) {
      World w(stack(k, passes));
      ASSERT_TRUE(w.plan().scale);
      w.step();
      const double left = kOverlap * std::pow((1.0 - k) / (2.0 - k), passes);
      SCOPED_TRACE(testing::Message() << "k = " << k << ", passes = " << passes);
      EXPECT_NEAR(w.ball(0).position.y(), kRadius, 1e-12);
      EXPECT_NEAR(w.ball(1).position.y(), 3.0 * kRadius - left, 1e-12);
      EXPECT_EQ(w.ball(0).position.x(), 0.0);
      EXPECT_EQ(w.ball(1).position.x(), 0.0);
    }
  }
}

TEST(ScaleShock, FullShockClearsAStackInOnePass) {
  World w(stack(1.0, 1));
  w.step();
  EXPECT_NEAR(w.ball(0).position.y(), kRadius, 1e-12);
  EXPECT_NEAR(w.ball(1).position.y(), 3.0 * kRadius, 1e-12);
}

// A slanted pair floating under the same weak gravity: ball 1 lies below
// and to the right of ball 0, along n = (cos t, -sin t) with t = 30 degrees,
// overlapping by d. Only the move along gravity, d sin t, is shared with the
// lower ball weighted 1 - k sin t: ball 0 rises d sin t / (2 - k sin t) and
// ball 1 sinks d sin t (1 - k sin t) / (2 - k sin t). The move across
// gravity, d cos t, is shared evenly (equal masses), so the pair's centre
// does not shift sideways, and one pass leaves the two exactly touching.
TEST(ScaleShock, OnlyTheMoveAlongGravityIsSharedUnevenly) {
  const double t = std::numbers::pi / 6.0, c = std::cos(t), sn = std::sin(t);
  const double reach = 2.0 * kRadius;
  for (const double k : {0.0, 0.7, 1.0}) {
    BallDef upper = restingBall(5.0), lower = restingBall(5.0);
    lower.position = upper.position + (reach - kOverlap) * Vec2(c, -sn);
    World w(pair(upper, lower, {0.0, -1e-9}, k));
    ASSERT_TRUE(w.plan().scale);
    w.step();
    SCOPED_TRACE(testing::Message() << "k = " << k);
    const Vec2 up = w.ball(0).position, low = w.ball(1).position;
    EXPECT_NEAR(up.x(), upper.position.x() - 0.5 * kOverlap * c, 1e-12);
    EXPECT_NEAR(low.x(), lower.position.x() + 0.5 * kOverlap * c, 1e-12);
    EXPECT_NEAR(up.x() + low.x(), upper.position.x() + lower.position.x(), 1e-12);
    EXPECT_NEAR(up.y(), upper.position.y() + kOverlap * sn / (2.0 - k * sn), 1e-12);
    EXPECT_NEAR(low.y(), lower.position.y() - kOverlap * sn * (1.0 - k * sn) / (2.0 - k * sn),
                1e-12);
    EXPECT_NEAR((low - up).norm(), reach, 1e-12);
  }
}

// Without gravity there is no "lower" ball: the overlap is shared by inverse
// mass whatever k is. Masses 1 and 3 kg, overlap d along x: the light ball
// moves 3 d / 4 to the left, the heavy one d / 4 to the right, and the centre
// of mass stays put.
TEST(ScaleShock, WithoutGravityTheShareIsByInverseMass) {
  for (const double k : {0.0, 0.7, 1.0}) {
    BallDef light = restingBall(0.0), heavy = restingBall(0.0);
    heavy.position = {2.0 * kRadius - kOverlap, 0.0};
    heavy.mass = 3.0;
    World w(pair(light, heavy, {0.0, 0.0}, k));
    ASSERT_TRUE(w.plan().scale);
    w.step();
    SCOPED_TRACE(testing::Message() << "k = " << k);
    EXPECT_NEAR(w.ball(0).position.x(), -0.75 * kOverlap, 1e-15);
    EXPECT_NEAR(w.ball(1).position.x(), 2.0 * kRadius - 0.75 * kOverlap, 1e-15);
    EXPECT_NEAR(1.0 * w.ball(0).position.x() + 3.0 * w.ball(1).position.x(),
                3.0 * (2.0 * kRadius - kOverlap), 1e-14);
  }
}

}  // namespace
}  // namespace particles
