// "Skip what the scene doesn't need": World::plan() switches stages off only
// when the physics cannot need them, and a skipped stage changes nothing.
//
// Physics behind the tangential flag: with mu = 0 at every contact there is no
// tangential impulse, and a normal impulse passes through the centres, so no
// contact can change a spin; without torques nothing else can either. Spins
// are then constant and each angle grows by dt w per step.
#include <gtest/gtest.h>

#include <vector>

#include "particles/world.h"
#include "physics_test_support.h"

namespace {

using namespace physics_test;
using particles::ContactMaterial;

// Spinning balls in a box under gravity, bound to collide with each other and
// with the walls.
particles::SceneDef spinningBalls(double mu, bool walls) {
  particles::SceneDef scene;
  scene.gravity = Vec2(0.0, -9.81);
  scene.contact = ContactMaterial{0.8, mu};
  if (walls) scene.walls = particles::boxWalls(Vec2(0.0, 0.0), Vec2(6.0, 6.0));
  Random rand(0x5eed'0031);
  for (int i = 0; i < 12; ++i) {
    particles::BallDef b;
    b.radius = 0.4;
    b.position = Vec2(0.5 + 1.0 * (i % 5), 0.5 + 1.0 * (i / 5));
    b.velocity = Vec2(rand.uniform(-4.0, 4.0), rand.uniform(-4.0, 4.0));
    b.angularVelocity = rand.uniform(-6.0, 6.0);
    b.angle = rand.uniform(-1.0, 1.0);
    scene.balls.push_back(b);
  }
  return scene;
}

TEST(StagePlan, NoWallsMeansNoWallStage) {
  EXPECT_FALSE(particles::World(spinningBalls(0.0, false)).plan().walls);
  EXPECT_TRUE(particles::World(spinningBalls(0.0, true)).plan().walls);
}

// Runs the scene and checks that every spin stays exactly constant and every
// angle follows theta += dt w; returns the number of contacts met.
long long expectSpinsUntouched(const particles::SceneDef& scene, int steps) {
  particles::World world(scene);
  std::vector<double> angle;
  for (const particles::BallDef& b : scene.balls) angle.push_back(b.angle);
  long long contacts = 0;
  for (int s = 0; s < steps; ++s) {
    world.step();
    contacts += world.stats().contacts;
    for (std::size_t i = 0; i < world.ballCount(); ++i) {
      const double w = scene.balls[i].angularVelocity;
      angle[i] += scene.dt * w;
      EXPECT_EQ(world.ball(i).angularVelocity, w) << "ball " << i << ", step " << s + 1;
      EXPECT_EQ(world.ball(i).angle, angle[i]) << "ball " << i << ", step " << s + 1;
    }
    if (::testing::Test::HasFailure()) break;
  }
  return contacts;
}

TEST(StagePlan, SmoothSceneWithoutTorquesSkipsTangentialWorkAndKeepsSpins) {
  particles::SceneDef scene = spinningBalls(0.0, true);
  particles::ForceDef push;  // a force, but no torque
  push.type = particles::ForceType::Constant;
  push.ball = 2;
  push.force = Vec2(3.0, 1.0);
  scene.forces.push_back(push);
  const particles::World world(scene);
  EXPECT_FALSE(world.plan().tangential);
  EXPECT_FALSE(world.plan().torques);
  EXPECT_TRUE(world.plan().spin) << "the balls spin initially: angles must still advance";
  EXPECT_GT(expectSpinsUntouched(scene, 2000), 100) << "the balls must actually collide";
}

// Friction mixes to 0 as soon as one side is smooth (a smooth surface cannot
// grip): one grippy ball among smooth balls and smooth walls grips nothing.
TEST(StagePlan, OneGrippyBallAmongSmoothBodiesGripsNothing) {
  particles::SceneDef scene = spinningBalls(0.0, true);
  scene.balls[0].friction = 0.8;
  EXPECT_FALSE(particles::World(scene).plan().tangential);
  EXPECT_GT(expectSpinsUntouched(scene, 2000), 100);
  // With a grippy wall it can grip.
  scene.walls[0].friction = 0.8;
  EXPECT_TRUE(particles::World(scene).plan().tangential);
}

// The converse, so the two tests above are not vacuous: with friction the
// stage is on and the same collisions do change spins.
TEST(StagePlan, FrictionTurnsTheTangentialStageOnAndSpinsChange) {
  const particles::SceneDef scene = spinningBalls(0.5, true);
  particles::World world(scene);
  EXPECT_TRUE(world.plan().tangential);
  world.run(2000);
  int changed = 0;
  for (std::size_t i = 0; i < world.ballCount(); ++i)
    changed += world.ball(i).angularVelocity != scene.balls[i].angularVelocity;
  EXPECT_EQ(changed, static_cast<int>(world.ballCount()));
}

// Nothing can rotate (no spin, no friction, no torque): angles are not
// integrated, and stay what the scene said.
TEST(StagePlan, SceneThatCannotRotateKeepsItsAngles) {
  particles::SceneDef scene = spinningBalls(0.0, true);
  for (particles::BallDef& b : scene.balls) b.angularVelocity = 0.0;
  particles::World world(scene);
  EXPECT_FALSE(world.plan().spin);
  world.run(1000);
  for (std::size_t i = 0; i < world.ballCount(); ++i) {
    EXPECT_EQ(world.ball(i).angle, scene.balls[i].angle);
    EXPECT_EQ(world.ball(i).angularVelocity, 0.0);
  }
}

TEST(StagePlan, TorqueTurnsTheSpinStageOn) {
  particles::SceneDef scene = spinningBalls(0.0, false);
  for (particles::BallDef& b : scene.balls) b.angularVelocity = 0.0;
  particles::ForceDef twist;
  twist.type = particles::ForceType::Constant;
  twist.torque = 0.5;
  scene.forces.push_back(twist);
  particles::World world(scene);
  EXPECT_TRUE(world.plan().torques);
  EXPECT_TRUE(world.plan().spin);
  EXPECT_FALSE(world.plan().tangential);
  world.step();
  EXPECT_GT(world.ball(0).angularVelocity, 0.0);
}

}  // namespace
