// reset() must be indistinguishable from a fresh Box2DWorld: Box2D keeps
// contacts, warm-starting impulses and broad-phase proxies from step to step,
// and any of them surviving a reset would change later steps. Compared bit for
// bit, at every step, over scenes with contacts, walls, friction, forces.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "particles/reference/box2d_world.h"
#include "reference_test_support.h"

namespace particles::reference {
namespace {

using testing::ball;
using testing::openScene;

bool sameBits(double x, double y) {
  return std::memcmp(&x, &y, sizeof x) == 0;
}

// Every ball's state at every step of a run.
std::vector<double> trajectory(Box2DWorld& world, long long steps) {
  std::vector<double> out;
  for (long long s = 0; s < steps; ++s) {
    world.step();
    for (std::size_t i = 0; i < world.ballCount(); ++i) {
      const BallState b = world.ball(i);
      out.insert(out.end(), {b.position.x(), b.position.y(), b.velocity.x(), b.velocity.y(),
                             b.angle, b.angularVelocity});
    }
  }
  return out;
}

void expectSameBits(const std::vector<double>& fresh, const std::vector<double>& reused,
                    const std::string& what) {
  ASSERT_EQ(fresh.size(), reused.size()) << what;
  for (std::size_t k = 0; k < fresh.size(); ++k)
    ASSERT_TRUE(sameBits(fresh[k], reused[k]))
        << what << ": value " << k << " " << fresh[k] << " vs " << reused[k];
}

SceneDef obliqueSpinning() {
  BallDef a = ball({-0.6, 0.0}, {1.0, 0.2});
  a.angularVelocity = 5.0;
  BallDef b = ball({0.6, 0.3}, {-1.0, 0.0}, 0.4, 0.7);
  b.friction = kNoSlip;
  return openScene({a, b}, {0.8, 0.4});
}

SceneDef boxWithGravityAndPull() {
  SceneDef s =
      openScene({ball({-1.0, 0.0}, {3.0, 1.0}), ball({1.0, 0.5}, {-2.0, 0.0}, 0.3)}, {0.7, 0.5});
  s.gravity = {0.0, -9.81};
  s.walls = boxWalls({-2.0, -2.0}, {2.0, 2.0});
  ForceDef pull;
  pull.ball = 1;
  pull.target = {0.0, 1.5};
  pull.stiffness = 20.0;
  pull.end = 0.3;
  s.forces = {pull};
  return s;
}

SceneDef crowdedBox(unsigned seed, int n) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<BallDef> balls;
  for (int i = 0; i < n; ++i) {
    BallDef b = ball({2.5 * u(rng), 2.5 * u(rng)}, {4.0 * u(rng), 4.0 * u(rng)},
                     0.2 + 0.1 * (u(rng) + 1.0), 1.0 + u(rng) * 0.5);
    b.angularVelocity = 10.0 * u(rng);
    if (i % 3 == 0) b.friction = kNoSlip;
    if (i % 4 == 0) b.restitution = 0.2;
    balls.push_back(b);
  }
  SceneDef s = openScene(balls, {0.9, 0.3});
  s.gravity = {0.0, -3.0};
  s.walls = boxWalls({-3.0, -3.0}, {3.0, 3.0});
  ForceDef spin;
  spin.type = ForceType::Constant;
  spin.ball = 0;
  spin.force = {1.0, 2.0};
  spin.torque = 0.5;
  spin.start = 0.05;
  s.forces = {spin};
  return s;
}

std::vector<SceneDef> scenes() {
  return {obliqueSpinning(), boxWithGravityAndPull(), crowdedBox(1, 12),
          crowdedBox(2, 12), crowdedBox(3, 5),        openScene({ball({0.0, 0.0}, {1.0, 0.0})})};
}

TEST(Box2DReset, IsBitIdenticalToAFreshWorld) {
  const long long steps = 400;
  const Box2DSettings settings{.dt = 1e-3};
  // One world reused for every scene, starting from a different scene and
  // left mid-run (contacts alive, impulses warm) before each reset.
  Box2DWorld reused(crowdedBox(9, 20), settings);
  reused.run(123);
  for (const SceneDef& scene : scenes()) {
    Box2DWorld fresh(scene, settings);
    const std::vector<double> expected = trajectory(fresh, steps);

    reused.reset(scene);
    EXPECT_EQ(reused.stepIndex(), 0);
    EXPECT_EQ(reused.time(), 0.0);
    EXPECT_EQ(reused.ballCount(), scene.balls.size());
    EXPECT_EQ(reused.wallCount(), scene.walls.size());
    expectSameBits(expected, trajectory(reused, steps), "after another scene");
    // Reset to the same scene after running it: contacts of the same bodies
    // would be the most tempting to survive.
    reused.reset(scene);
    expectSameBits(expected, trajectory(reused, steps), "same scene again");
    reused.run(77);  // leave it mid-run for the next scene
  }
}

TEST(Box2DReset, ForgetsPullTargetsAndLimitHits) {
  SceneDef scene = boxWithGravityAndPull();
  scene.balls[0].velocity = {2500.0, 0.0};  // clamped by b2_maxTranslation
  const Box2DSettings settings = Box2DSettings::forScene(scene);
  Box2DWorld fresh(scene, settings);
  const std::vector<double> expected = trajectory(fresh, 50);

  Box2DWorld reused(scene, settings);
  reused.setPullTarget(0, {-1.0, -1.0});
  reused.run(10);
  EXPECT_GT(reused.limitHits().translation, 0);
  reused.reset(scene);
  EXPECT_EQ(reused.limitHits().translation, 0);
  expectSameBits(expected, trajectory(reused, 50), "after setPullTarget");
}

TEST(Box2DReset, AFailedResetKeepsTheWorld) {
  const SceneDef scene = obliqueSpinning();
  Box2DWorld world(scene, Box2DSettings::forScene(scene));
  world.run(5);
  const BallState before = world.ball(1);
  SceneDef bad = scene;
  bad.balls[0].mass = -1.0;
  EXPECT_THROW(world.reset(bad), std::invalid_argument);
  EXPECT_EQ(world.stepIndex(), 5);
  EXPECT_EQ(world.ball(1).position, before.position);
  world.step();  // still a working world
  EXPECT_EQ(world.stepIndex(), 6);
}

TEST(Box2DReset, MovedWorldKeepsItsState) {
  const SceneDef scene = obliqueSpinning();
  Box2DWorld a(scene, Box2DSettings::forScene(scene));
  a.run(3);
  Box2DWorld b(std::move(a));
  EXPECT_EQ(b.stepIndex(), 3);
  Box2DWorld c(scene, Box2DSettings::forScene(scene));
  c.run(3);
  EXPECT_EQ(b.ball(0).position, c.ball(0).position);
}

}  // namespace
}  // namespace particles::reference
