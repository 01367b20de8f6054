// sceneText() reads back through the loader as the same scene.
#include <gtest/gtest.h>

#include "particles/scene_writer.h"
#include "particles/scenefile.h"

namespace particles {
namespace {

TEST(SceneWriter, RoundTripsEveryField) {
  SceneDef s;
  s.name = "round \"trip\"";
  s.gravity = {0.1, -9.81};
  s.contact = {0.3, kNoSlip};
  s.walls = boxWalls({0, 0}, {4, 3});
  s.walls[1].restitution = 0.25;
  s.walls[2].friction = 0.1;
  s.walls[3].oneSided = false;  // the others are one-sided, as boxWalls makes them
  BallDef a;
  a.position = {1.0 / 3.0, 1};
  a.velocity = {2e-7, -1e6};
  a.angularVelocity = -3.5;
  a.angle = 0.7;
  a.radius = 0.3;
  a.mass = 1e-6;
  BallDef b = a;
  b.position = {3, 2};
  b.inertia = 0.01;
  b.friction = 0.0;
  b.restitution = 1.0;
  s.balls = {a, b};
  ForceDef pull;
  pull.ball = 1;
  pull.target = {2, 2};
  pull.stiffness = 5;
  pull.end = 1.5;
  ForceDef constant;
  constant.type = ForceType::Constant;
  constant.force = {4, -2};
  constant.torque = 0.25;
  constant.start = -1;
  s.forces = {pull, constant};
  s.dt = 1.0 / 600.0;
  s.duration = 2.5;
  s.solver.contactPasses = 7;
  s.solver.correctionPasses = 3;
  s.solver.gridThreshold = 0;
  s.solver.sweptWalls = true;  // not the defaults: the writer must carry them
  s.solver.sweptBalls = true;
  s.solver.scaleSequentialImpacts = true;
  s.solver.scaleVelocityShock = false;

  const SceneDef r = parseScene(sceneText(s), "written.json");
  EXPECT_EQ(r.name, s.name);
  EXPECT_EQ(r.gravity, s.gravity);
  EXPECT_EQ(r.contact.restitution, 0.3);
  EXPECT_EQ(r.contact.friction, kNoSlip);
  ASSERT_EQ(r.walls.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(r.walls[i].a, s.walls[i].a);
    EXPECT_EQ(r.walls[i].b, s.walls[i].b);
    EXPECT_EQ(r.walls[i].restitution, s.walls[i].restitution);
    EXPECT_EQ(r.walls[i].friction, s.walls[i].friction);
    EXPECT_EQ(r.walls[i].oneSided, s.walls[i].oneSided);
  }
  ASSERT_EQ(r.balls.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(r.balls[i].position, s.balls[i].position);
    EXPECT_EQ(r.balls[i].velocity, s.balls[i].velocity);
    EXPECT_EQ(r.balls[i].angle, s.balls[i].angle);
    EXPECT_EQ(r.balls[i].angularVelocity, s.balls[i].angularVelocity);
    EXPECT_EQ(r.balls[i].radius, s.balls[i].radius);
    EXPECT_EQ(r.balls[i].mass, s.balls[i].mass);
    EXPECT_EQ(r.balls[i].resolvedInertia(), s.balls[i].resolvedInertia());
    EXPECT_EQ(r.balls[i].restitution, s.balls[i].restitution);
    EXPECT_EQ(r.balls[i].friction, s.balls[i].friction);
  }
  ASSERT_EQ(r.forces.size(), 2u);
  EXPECT_EQ(r.forces[0].type, ForceType::Pull);
  EXPECT_EQ(r.forces[0].target, pull.target);
  EXPECT_EQ(r.forces[0].stiffness, 5.0);
  EXPECT_EQ(r.forces[0].end, 1.5);
  EXPECT_EQ(r.forces[1].type, ForceType::Constant);
  EXPECT_EQ(r.forces[1].force, constant.force);
  EXPECT_EQ(r.forces[1].torque, 0.25);
  EXPECT_EQ(r.forces[1].start, -1.0);
  EXPECT_TRUE(std::isinf(r.forces[1].end));
  EXPECT_EQ(r.dt, s.dt);
  EXPECT_EQ(r.duration, 2.5);
  EXPECT_EQ(r.solver.contactPasses, 7);
  EXPECT_EQ(r.solver.correctionPasses, 3);
  EXPECT_EQ(r.solver.gridThreshold, 0);
  EXPECT_TRUE(r.solver.sweptWalls);
  EXPECT_TRUE(r.solver.sweptBalls);
  EXPECT_TRUE(r.solver.scaleSequentialImpacts);
  EXPECT_FALSE(r.solver.scaleVelocityShock);
  EXPECT_EQ(r.solver.scaleSubsteps, 0);  // the rigid step: no soft keys written
}

TEST(SceneWriter, RoundTripsTheSoftStep) {
  SceneDef s;
  s.balls = {BallDef{}};
  s.dt = 0.01;
  s.solver.scaleSubsteps = 4;
  s.solver.scaleContactDampingRatio = 2.5;
  s.solver.scaleContactPushSpeed = 0.75;
  // 0: the engine's own spring, a quarter of the substep rate; not written.
  SceneDef r = parseScene(sceneText(s), "written.json");
  EXPECT_EQ(r.solver.scaleSubsteps, 4);
  EXPECT_EQ(r.solver.scaleContactHertz, 0.0);
  EXPECT_EQ(r.solver.scaleContactDampingRatio, 2.5);
  EXPECT_EQ(r.solver.scaleContactPushSpeed, 0.75);

  s.solver.scaleContactHertz = 30.0;
  r = parseScene(sceneText(s), "written.json");
  EXPECT_EQ(r.solver.scaleContactHertz, 30.0);
  // Above the bound (100 Hz here) the engine clamps to it; so does the writer,
  // or the loader would refuse what it wrote.
  s.solver.scaleContactHertz = 500.0;
  r = parseScene(sceneText(s), "written.json");
  EXPECT_EQ(r.solver.scaleContactHertz, 0.25 / (0.01 / 4));
}

}  // namespace
}  // namespace particles
