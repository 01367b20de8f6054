// The large-scene path numbers the balls in the grid's cell order
// (docs/scale.md, "Cell order"), whatever order the scene lists them in, and
// carries each contact's impulses to the next step by the balls, not by
// their numbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <random>
#include <vector>

#include "large_path_scene.h"
#include "particles/pile/pile_scene.h"
#include "particles/world.h"

namespace particles::pile {
namespace {

// The same pile listed in another order ends in the same state, bit for bit,
// ball for ball: the solve order, the strips and the warm start follow the
// positions only.
TEST(ScaleOrder, ARelistedPileEndsInTheSameStateBallForBall) {
  PileParams p;
  p.count = 1500;
  p.polydisperse = true;
  p.threads = 2;
  SceneDef scene = makePile(p);
  scene.solver.scaleParallelFrom = 0;
  // listed[k] = scene.balls[order[k]]: reversed, then shuffled in blocks.
  std::vector<std::size_t> order(scene.balls.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = order.size() - 1 - k;
  std::shuffle(order.begin() + 300, order.end(), std::mt19937_64(7));
  SceneDef listed = scene;
  for (std::size_t k = 0; k < order.size(); ++k) listed.balls[k] = scene.balls[order[k]];

  World world(scene), relisted(listed);
  ASSERT_TRUE(world.plan().scale);
  world.run(240);  // landed: contacts are warm-started
  relisted.run(240);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const BallState a = world.ball(order[k]), b = relisted.ball(k);
    ASSERT_EQ(a.position, b.position) << k;
    ASSERT_EQ(a.velocity, b.velocity) << k;
    ASSERT_EQ(a.angle, b.angle) << k;
    ASSERT_EQ(a.angularVelocity, b.angularVelocity) << k;
  }
}

// Three 1 kg balls stacked on the floor, e = 0, four velocity iterations and
// no support sweep: four Gauss-Seidel passes hold the stack exactly only
// with the last step's impulses (the floor's 3 m g dt, then 2 m g dt and
// m g dt); from none they leave the upper balls sinking at 0.042 m/s. A fourth ball falls from high
// up to the left of the stack: while it passes the stack's grid rows it is numbered before the
// stack's balls, so their numbers change under the warm start.
TEST(ScaleOrder, TheWarmStartFollowsBallsWhoseNumbersChange) {
  constexpr double kRadius = 0.5, kGravity = 10.0, kDt = 1e-2;
  SceneDef s = test::largePathScene(kDt, kGravity, {0.0, 0.0}, {10.0, 12.0});
  test::addStack(s, 8.0, 3, kRadius);
  test::addStack(s, 1.0, 1, kRadius);
  s.balls[3].position.y() = 9.0;  // the faller
  s.solver.scaleVelocityIterations = 4;
  s.solver.scaleVelocityShock = false;
  // Plain Gauss-Seidel: over-relaxed, 4 iterations leave this stack bouncing
  // (SolverSettings::scaleOverRelaxation), and this test is about the warm
  // start alone.
  s.solver.scaleOverRelaxation = 1.0;
  World world(s);
  ASSERT_TRUE(world.plan().scale);
  world.recordImpacts(true);

  // The stack settles: the impulses build up over the first steps.
  world.run(60);
  ASSERT_GT(world.ball(3).position.y(), 5.0);  // still above the stack
  const double weight = 1.0 * kGravity * kDt;  // N s per step
  for (int step = 60; step < 200; ++step) {
    world.step();
    SCOPED_TRACE(testing::Message() << "step " << step);
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_LT(world.ball(k).velocity.norm(), 1e-9 * kGravity * kDt) << k;
    double floor = 0.0, lower = 0.0, upper = 0.0;
    for (const ImpactEvent& e : world.impacts()) {
      if (e.wall && e.a == 0) floor = e.normalImpulse;
      if (!e.wall && e.a == 0 && e.b == 1) lower = e.normalImpulse;
      if (!e.wall && e.a == 1 && e.b == 2) upper = e.normalImpulse;
    }
    EXPECT_NEAR(floor, 3.0 * weight, 1e-9 * weight);
    EXPECT_NEAR(lower, 2.0 * weight, 1e-9 * weight);
    EXPECT_NEAR(upper, 1.0 * weight, 1e-9 * weight);
  }
  // The fourth ball has passed the stack's rows and lies on the floor.
  EXPECT_NEAR(world.ball(3).position.y(), kRadius, 1e-3);
}

}  // namespace
}  // namespace particles::pile
