// The session: the display never changes the physics. Without a pull the
// worlds are bit-identical to plain ones; the pull is the handout's
// F = k (M - O) in both engines; the time scale changes the number of
// steps, never dt.
#include <gtest/gtest.h>

#include <cmath>

#include "particles/viewer/session.h"
#include "particles/viewer/viewer_app.h"

namespace particles::viewer {
namespace {

// Three balls in a box under gravity, with friction and spin: every stage
// of the step is in use.
SceneDef busyScene() {
  SceneDef scene;
  scene.gravity = {0.0, -9.81};
  scene.contact = {0.9, 0.2};
  scene.walls = boxWalls({0.0, 0.0}, {4.0, 3.0});
  BallDef a, b, c;
  a.position = {1.0, 2.0};
  a.velocity = {3.0, 0.0};
  a.radius = 0.3;
  b.position = {2.5, 1.0};
  b.velocity = {-1.0, 2.0};
  b.angularVelocity = 5.0;
  b.radius = 0.4;
  b.mass = 1.5;
  c.position = {3.2, 2.4};
  c.velocity = {0.0, -1.0};
  c.radius = 0.25;
  c.mass = 0.5;
  scene.balls = {a, b, c};
  return scene;
}

SceneDef freeBall(double mass) {
  SceneDef scene;
  BallDef ball;
  ball.position = {1.0, 2.0};
  ball.mass = mass;
  scene.balls = {ball};
  return scene;
}

void expectSame(const BallState& a, const BallState& b) {
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.velocity, b.velocity);
  EXPECT_EQ(a.angle, b.angle);
  EXPECT_EQ(a.angularVelocity, b.angularVelocity);
}

TEST(Session, UnheldRunIsBitIdenticalToPlainWorlds) {
  for (const SceneDef& scene : {busyScene(), freeBall(2.0)}) {
    Session session(scene);
    World plain(scene);
    reference::Box2DWorld plainBox2D(scene, reference::Box2DSettings::forScene(scene));
    for (int frame = 0; frame < 90; ++frame) session.advance(kFrameSeconds);
    plain.run(session.engine().stepIndex());
    plainBox2D.run(session.engine().stepIndex());
    ASSERT_TRUE(session.hasBox2D());
    ASSERT_EQ(session.box2d()->stepIndex(), plain.stepIndex());
    for (std::size_t i = 0; i < scene.balls.size(); ++i) {
      expectSame(session.engine().ball(i), plain.ball(i));
      expectSame(session.box2d()->ball(i), plainBox2D.ball(i));
    }
  }
}

TEST(Session, SixtyFramesOfASixtiethAreExactlyOneSecond) {
  Session session(freeBall(1.0));  // dt = 1e-3
  long long steps = 0;
  for (int frame = 0; frame < 60; ++frame) steps += session.advance(kFrameSeconds);
  EXPECT_EQ(steps, 1000);
  EXPECT_EQ(session.engine().stepIndex(), 1000);
}

TEST(Session, TimeScaleRunsMoreStepsNotLongerOnes) {
  Session session(freeBall(1.0));
  session.faster();
  EXPECT_EQ(session.timeScale(), 2.0);
  EXPECT_EQ(session.advance(0.5), 1000);
  EXPECT_EQ(session.engine().dt(), 1e-3);
  session.slower();
  session.slower();
  EXPECT_EQ(session.timeScale(), 0.5);
  EXPECT_EQ(session.advance(0.5), 250);
  for (int i = 0; i < 20; ++i) session.slower();
  EXPECT_EQ(session.timeScaleLog2(), kMinTimeScaleLog2);
  for (int i = 0; i < 20; ++i) session.faster();
  EXPECT_EQ(session.timeScaleLog2(), kMaxTimeScaleLog2);
}

TEST(Session, PauseStopsTimeAndSingleStepStillSteps) {
  Session session(freeBall(1.0));
  session.setPaused(true);
  EXPECT_EQ(session.advance(1.0), 0);
  session.stepOnce();
  EXPECT_EQ(session.engine().stepIndex(), 1);
  EXPECT_EQ(session.box2d()->stepIndex(), 1);
  // Time spent paused is not owed afterwards.
  session.setPaused(false);
  EXPECT_EQ(session.advance(0.0105), 10);
}

TEST(Session, PullIsKTimesCursorMinusCentreInBothEngines) {
  const double mass = 2.0;
  Session session(freeBall(mass));
  const double k = session.pullStiffness(0);
  EXPECT_EQ(k, kPullStiffnessPerKg * mass);
  const Vec2 cursor(3.0, 1.0), centre(1.0, 2.0);
  session.hold(0, cursor);
  session.stepOnce();
  const double dt = session.engine().dt();
  // One semi-implicit step from rest: v = dt F / m.
  const Vec2 expected = dt * k * (cursor - centre) / mass;
  EXPECT_LT((session.engine().ball(0).velocity - expected).norm(), 1e-15);
  // Box2D works in float: the same force within float rounding.
  EXPECT_LT((session.box2d()->ball(0).velocity - expected).norm(), 1e-6 * expected.norm());
}

TEST(Session, ReleasedBallKeepsItsVelocity) {
  Session session(freeBall(1.0));
  session.hold(0, {3.0, 2.0});
  for (int i = 0; i < 10; ++i) session.stepOnce();
  session.release();
  const BallState before = session.engine().ball(0);
  session.stepOnce();
  EXPECT_EQ(session.engine().ball(0).velocity, before.velocity);  // no force at all
  EXPECT_EQ(session.engine().ball(0).position, before.position + 1e-3 * before.velocity);
}

TEST(Session, RestartGoesBackToTheStartAndLetsGo) {
  Session session(busyScene());
  session.hold(1, {0.5, 0.5});
  for (int frame = 0; frame < 10; ++frame) session.advance(kFrameSeconds);
  session.restart();
  EXPECT_FALSE(session.held());
  EXPECT_EQ(session.engine().stepIndex(), 0);
  EXPECT_EQ(session.box2d()->stepIndex(), 0);
  EXPECT_EQ(session.engine().ball(1).position, busyScene().balls[1].position);
}

TEST(Session, HoldingAMissingBallThrows) {
  Session session(freeBall(1.0));
  EXPECT_THROW(session.hold(1, {0.0, 0.0}), std::out_of_range);
}

TEST(Session, ImpactsOfAFrameAreMergedPerContact) {
  // A ball resting on the floor touches it every step: one merged impact.
  SceneDef scene;
  scene.gravity = {0.0, -9.81};
  scene.contact = {0.0, 0.0};
  scene.walls = {WallDef{{-5.0, 0.0}, {5.0, 0.0}, {}, {}}};
  BallDef ball;
  ball.position = {0.0, 0.5};
  scene.balls = {ball};
  Session session(scene);
  ASSERT_GT(session.advance(kFrameSeconds), 1);
  ASSERT_EQ(session.impacts().size(), 1u);
  EXPECT_TRUE(session.impacts()[0].wall);
  // The floor cancels gravity: about m g per second of impulse.
  EXPECT_NEAR(session.impacts()[0].normalImpulse, 9.81 * 16e-3, 9.81 * 2e-3);
}

TEST(Pick, TheBallDrawnOnTopWins) {
  SceneDef scene;
  BallDef a, b;
  a.position = {0.0, 0.0};
  a.radius = 1.0;
  b.position = {0.5, 0.0};
  b.radius = 0.5;
  scene.balls = {a, b};
  const Vec2 still(0.0, 0.0);
  const std::vector<BallState> s = {{a.position, still, 0.0, 0.0}, {b.position, still, 0.0, 0.0}};
  EXPECT_EQ(pickBall(s, scene, {0.6, 0.1}), 1);
  EXPECT_EQ(pickBall(s, scene, {-0.6, 0.1}), 0);
  EXPECT_FALSE(pickBall(s, scene, {2.0, 0.0}));
}

}  // namespace
}  // namespace particles::viewer
