// Shock propagation in the large-scene path's velocities
// (SolverSettings::scaleVelocityShock, docs/scale.md), against the closed form
// of a three-ball stack on a floor.
//
// Balls 0, 1 and 2 (radius r, 1 kg) sit on top of each other on the floor,
// touching, at rest, e = 0. The step adds g dt downwards to each. With one
// velocity iteration the rows are solved in cell order: (0, 1) finds no
// approach (both move at -g dt), (0, floor) stops ball 0, (1, 2) finds no
// approach. After the iteration ball 0 is at rest and balls 1 and 2 still
// move at -g dt: the stack sinks into ball 0. The sweep then takes (0, 1),
// which approaches at g dt: ball 1, the upper, alone stops; then (1, 2):
// ball 2 stops. So with the sweep the whole stack is at rest after one step,
// exactly, and without it balls 1 and 2 keep -g dt.
#include <gtest/gtest.h>

#include "large_path_scene.h"
#include "particles/world.h"

namespace particles {
namespace {

constexpr double kRadius = 0.5;    // m
constexpr double kGravity = 10.0;  // m/s^2
constexpr double kDt = 1e-2;       // s

SceneDef stack(bool sweep) {
  SceneDef s = test::largePathScene(kDt, kGravity, {-10.0, 0.0}, {10.0, 10.0});
  test::addStack(s, 0.0, 3, kRadius);
  s.solver.scaleVelocityIterations = 1;
  s.solver.scaleVelocityShock = sweep;
  return s;
}

TEST(ScaleVelocityShock, OneSweepHoldsAStackThatOneIterationLeavesSinking) {
  World with(stack(true));
  ASSERT_TRUE(with.plan().scale);
  with.step();
  for (std::size_t k = 0; k < 3; ++k) {
    SCOPED_TRACE(testing::Message() << "ball " << k);
    EXPECT_EQ(with.ball(k).velocity, Vec2::Zero());
    EXPECT_EQ(with.ball(k).angularVelocity, 0.0);
    EXPECT_EQ(with.ball(k).position.y(), (1.0 + 2.0 * static_cast<double>(k)) * kRadius);
  }

  World without(stack(false));
  without.step();
  EXPECT_EQ(without.ball(0).velocity, Vec2::Zero());
  EXPECT_EQ(without.ball(1).velocity, Vec2(0.0, -kGravity * kDt));
  EXPECT_EQ(without.ball(2).velocity, Vec2(0.0, -kGravity * kDt));
}

// The sweep only ever stops an approach: a stack whose balls part (the top
// one thrown upwards) is left as the iterations leave it, and no ball gains
// energy from it.
TEST(ScaleVelocityShock, APartingPairIsLeftAlone) {
  SceneDef s = stack(true);
  s.balls[2].velocity = {0.0, 3.0};
  World with(s);
  s.solver.scaleVelocityShock = false;
  World without(s);
  with.step();
  without.step();
  EXPECT_EQ(with.ball(2).velocity, without.ball(2).velocity);
  EXPECT_EQ(with.ball(2).velocity, Vec2(0.0, 3.0 - kGravity * kDt));
}

}  // namespace
}  // namespace particles
