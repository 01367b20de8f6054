// The Box2D twin moves as its scene says: free flight, gravity, forces and
// their time windows, pulls, one impact, Box2D's per-step clamps.
//
// Tolerances: Box2D works in float. One step adds h v to a position near |x|
// and rounds, an error of at most half a float ulp of |x|; n steps at most
// n ulp(|x|) / 2. The increment h v itself carries a few float roundings
// (dt, v and the product), 3 eps relative. Each test states its bound.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "particles/contact_impulse.h"
#include "particles/reference/box2d_world.h"
#include "reference_test_support.h"

namespace particles::reference {
namespace {

using testing::asFloat;
using testing::ball;
using testing::floatUlp;
using testing::kFloatEps;
using testing::openScene;

TEST(Box2DMotion, FreeFlightIsX0PlusVt) {
  BallDef b = ball({0.3, -0.2}, {1.5, -0.7});
  b.angularVelocity = 2.0;
  const SceneDef scene = openScene({b});
  Box2DWorld world(scene, Box2DSettings::forScene(scene));
  const long long n = 1000;
  world.run(n);
  const double t = world.time();
  EXPECT_DOUBLE_EQ(t, 1.0);

  const BallState s = world.ball(0);
  // No damping and no force: the velocity is the float start value, exactly.
  EXPECT_EQ(s.velocity.x(), asFloat(1.5));
  EXPECT_EQ(s.velocity.y(), asFloat(-0.7));
  EXPECT_EQ(s.angularVelocity, asFloat(2.0));
  for (int k = 0; k < 2; ++k) {
    const double x0 = b.position[k], v = b.velocity[k];
    const double reach = std::max(std::abs(x0), std::abs(x0 + v * t));
    const double tol = n * 0.5 * floatUlp(reach) + 3.0 * kFloatEps * std::abs(v) * t +
                       floatUlp(x0);  // x0 itself rounded to float
    EXPECT_NEAR(s.position[k], x0 + v * t, tol) << "axis " << k;
  }
  const double angleTol = n * 0.5 * floatUlp(2.0) + 3.0 * kFloatEps * 2.0;
  EXPECT_NEAR(s.angle, 2.0 * t, angleTol);
}

// Semi-implicit Euler (velocity first, then position), as in Box2D and the
// engine: v_n = v0 + n h g, x_n = x0 + v0 n h + g h^2 n (n + 1) / 2.
TEST(Box2DMotion, GravityGivesSemiImplicitEulerFreeFall) {
  SceneDef scene = openScene({ball({0.0, 10.0}, {0.5, 2.0})});
  scene.gravity = {0.0, -9.81};
  Box2DWorld world(scene, Box2DSettings::forScene(scene));
  const long long n = 500;
  const double h = scene.dt;
  world.run(n);
  const BallState s = world.ball(0);
  const double vy = 2.0 - 9.81 * h * n;
  const double y = 10.0 + 2.0 * h * n - 9.81 * h * h * n * (n + 1) / 2.0;
  // Each step adds h g (a few roundings, 4 eps relative) and rounds v.
  const double vTol = n * (0.5 * floatUlp(5.0) + 4.0 * kFloatEps * 9.81 * h);
  EXPECT_NEAR(s.velocity.y(), vy, vTol);
  EXPECT_EQ(s.velocity.x(), asFloat(0.5));
  EXPECT_NEAR(s.position.y(), y, n * 0.5 * floatUlp(11.0) + vTol * h * n);
}

TEST(Box2DMotion, ConstantForceAndTorqueOnlyInsideTheirWindow) {
  BallDef b = ball({0.0, 0.0}, {0.0, 0.0}, 0.5, 2.0);
  b.inertia = 0.4;
  SceneDef scene = openScene({b});
  ForceDef f;
  f.type = ForceType::Constant;
  f.force = {3.0, -1.0};
  f.torque = 0.8;
  // Active at t = 5, 6, 7, 8, 9 ms (step starts), away from rounding at the
  // window's edges.
  f.start = 4.5e-3;
  f.end = 9.5e-3;
  scene.forces = {f};
  Box2DWorld world(scene, Box2DSettings::forScene(scene));
  world.run(5);
  EXPECT_EQ(world.ball(0).velocity, Vec2(0.0, 0.0));
  EXPECT_EQ(world.ball(0).angularVelocity, 0.0);
  world.run(20);
  const double active = 5 * scene.dt;
  const BallState s = world.ball(0);
  // Five float accumulations of h F / m: 5 x (a few eps) relative.
  EXPECT_NEAR(s.velocity.x(), 3.0 / 2.0 * active, 20 * kFloatEps * 1.5 * active);
  EXPECT_NEAR(s.velocity.y(), -1.0 / 2.0 * active, 20 * kFloatEps * 0.5 * active);
  EXPECT_NEAR(s.angularVelocity, 0.8 / 0.4 * active, 20 * kFloatEps * 2.0 * active);
}

// The pull is a spring to the target: from rest the ball accelerates toward
// it. The expected trajectory is the same recurrence in double:
// v += h k (T - x) / m; x += h v, with x from the start of each step.
TEST(Box2DMotion, PullFromRestMovesTowardTheTarget) {
  SceneDef scene = openScene({ball({1.0, 2.0}, {0.0, 0.0}, 0.5, 2.0)});
  ForceDef pull;
  pull.type = ForceType::Pull;
  pull.target = {4.0, -2.0};
  pull.stiffness = 50.0;
  scene.forces = {pull};
  Box2DWorld world(scene, Box2DSettings::forScene(scene));

  world.step();
  const Vec2 d = pull.target - scene.balls[0].position;
  const Vec2 v1 = world.ball(0).velocity;
  const Vec2 expected = scene.dt * pull.stiffness / 2.0 * d;
  EXPECT_NEAR(v1.x(), expected.x(), 4 * kFloatEps * expected.norm());
  EXPECT_NEAR(v1.y(), expected.y(), 4 * kFloatEps * expected.norm());

  // omega = sqrt(k / m) = 5 rad/s: the continuous spring is at
  // |x - T| = d cos(omega t) = 0.54 d at t = 0.2 s, on its way in.
  Vec2 x = scene.balls[0].position, v = Vec2::Zero();
  const long long n = 200;
  for (long long s = 0; s < n; ++s) {
    v += scene.dt * pull.stiffness / 2.0 * (pull.target - x);
    x += scene.dt * v;
  }
  world.run(n - 1);
  const BallState s = world.ball(0);
  EXPECT_NEAR((s.position - pull.target).norm(), std::cos(1.0) * d.norm(), 0.01 * d.norm());
  // Float rounding feeds back through the spring, but over 200 steps of a
  // stable oscillator it stays at the 1e-6 level of the 5 m excursion.
  EXPECT_NEAR(s.position.x(), x.x(), 1e-5);
  EXPECT_NEAR(s.position.y(), x.y(), 1e-5);
  EXPECT_NEAR(s.velocity.x(), v.x(), 1e-5 * v.norm() + 1e-6);
  EXPECT_NEAR(s.velocity.y(), v.y(), 1e-5 * v.norm() + 1e-6);
}

TEST(Box2DMotion, SetPullTargetRedirectsThePull) {
  SceneDef scene = openScene({ball({0.0, 0.0}, {0.0, 0.0})});
  ForceDef pull;
  pull.target = {1.0, 0.0};
  pull.stiffness = 10.0;
  scene.forces = {pull};
  Box2DWorld world(scene, Box2DSettings::forScene(scene));
  world.setPullTarget(0, {0.0, -3.0});
  world.step();
  const Vec2 v = world.ball(0).velocity;
  EXPECT_EQ(v.x(), 0.0);
  EXPECT_NEAR(v.y(), -3.0 * 10.0 * scene.dt, 4 * kFloatEps * 0.03);
  EXPECT_THROW(world.setPullTarget(1, {0.0, 0.0}), std::out_of_range);
}

// One oblique impact of two spinning balls touching at the start of a step:
// for circles the normal and tangential rows decouple (the contact point is
// on the line of centres), so with >= 2 velocity iterations Box2D's step-one
// velocities equal the engine's closed-form impulse, up to float rounding and
// the lever arm Box2D measures to the middle of the 1e-6 m overlap.
class Box2DImpact : public ::testing::TestWithParam<double> {};

TEST_P(Box2DImpact, OneImpactMatchesTheClosedFormImpulse) {
  BallDef a = ball({0.0, 0.0}, {2.0, 0.7}, 0.5, 1.0);
  a.angularVelocity = 3.0;
  BallDef b = ball((1.0 - 1e-6) * Vec2(0.8, 0.6), {-1.0, -0.4}, 0.5, 3.0);  // overlap 1e-6 m
  b.angularVelocity = -2.0;
  b.inertia = 0.3;
  const SceneDef scene = openScene({a, b}, {0.6, GetParam()});
  Box2DWorld world(scene, Box2DSettings::forScene(scene));

  auto body = [&](std::size_t i) {
    const BallState s = world.ball(i);
    const BodyInfo info = world.bodyInfo(i);
    ContactBody c;
    c.velocity = s.velocity;
    c.angularVelocity = s.angularVelocity;
    c.invMass = 1.0 / info.mass;
    c.invInertia = 1.0 / info.inertia;
    c.leverArm = info.radius;
    return c;
  };
  ContactBody ca = body(0), cb = body(1);
  const Vec2 n = (world.ball(1).position - world.ball(0).position).normalized();
  const ContactImpulse impulse = resolveImpact(ca, cb, n, scene.contact);
  world.step();

  const double scale = 5.0;  // m/s, the speeds involved
  const double tol = 1e-5 * scale;
  EXPECT_NEAR(world.ball(0).velocity.x(), ca.velocity.x(), tol);
  EXPECT_NEAR(world.ball(0).velocity.y(), ca.velocity.y(), tol);
  EXPECT_NEAR(world.ball(1).velocity.x(), cb.velocity.x(), tol);
  EXPECT_NEAR(world.ball(1).velocity.y(), cb.velocity.y(), tol);
  EXPECT_NEAR(world.ball(0).angularVelocity, ca.angularVelocity, tol / 0.5);
  EXPECT_NEAR(world.ball(1).angularVelocity, cb.angularVelocity, tol / 0.5);
  const std::vector<ContactInfo> contacts = world.contacts();
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(contacts[0].normalImpulse, impulse.normal, 1e-5 * impulse.normal);
  EXPECT_NEAR(std::abs(contacts[0].tangentImpulse), std::abs(impulse.tangent),
              1e-5 * impulse.normal);
}

// 0.1 slides (the clamp binds), 0.6 and no-slip stick.
INSTANTIATE_TEST_SUITE_P(Friction, Box2DImpact, ::testing::Values(0.0, 0.1, 0.6, kNoSlip));

// Box2D's default restitution threshold (1 m/s) would make this slow impact
// inelastic; the twin's 0 bounces it with e = 1 like the engine: equal
// masses head-on exchange velocities.
TEST(Box2DMotion, SlowImpactsStillBounce) {
  const SceneDef scene =
      openScene({ball({0.0, 0.0}, {0.1, 0.0}), ball({0.9999, 0.0}, {-0.1, 0.0})}, {1.0, 0.0});
  Box2DWorld world(scene, Box2DSettings::forScene(scene));
  world.step();
  EXPECT_NEAR(world.ball(0).velocity.x(), -0.1, 1e-6);
  EXPECT_NEAR(world.ball(1).velocity.x(), 0.1, 1e-6);
}

// With one velocity iteration Box2D solves friction before any normal
// impulse exists, so a new contact gets no tangential impulse at all
// (checkBox2DRange flags this setting).
TEST(Box2DMotion, OneVelocityIterationLosesFriction) {
  BallDef a = ball({0.0, 0.0}, {1.0, 0.5});
  a.angularVelocity = 4.0;
  const SceneDef scene = openScene({a, ball({0.9999, 0.0}, {-1.0, 0.0})}, {0.5, kNoSlip});
  Box2DSettings settings = Box2DSettings::forScene(scene);
  settings.velocityIterations = 1;
  Box2DWorld world(scene, settings);
  world.step();
  EXPECT_EQ(world.ball(0).angularVelocity, asFloat(4.0));
  EXPECT_EQ(world.ball(1).angularVelocity, 0.0);
  EXPECT_EQ(world.ball(0).velocity.y(), asFloat(0.5));
  EXPECT_LT(world.ball(0).velocity.x(), 0.0);  // the normal impulse did act
}

// Box2D scales a velocity so that one step moves at most b2_maxTranslation
// (2 m) and turns at most b2_maxRotation (pi/2); limitHits() counts it.
TEST(Box2DMotion, PerStepClampsAreCounted) {
  BallDef fast = ball({0.0, 0.0}, {3000.0, 0.0});
  BallDef spinning = ball({100.0, 0.0}, {0.0, 0.0});
  spinning.angularVelocity = 2000.0;
  const SceneDef scene = openScene({fast, spinning});
  Box2DWorld world(scene, Box2DSettings::forScene(scene));
  world.step();
  EXPECT_NEAR(world.ball(0).velocity.x(), 2.0 / 1e-3, 1e-5 * 2000.0);
  EXPECT_NEAR(world.ball(1).angularVelocity, 0.5 * std::numbers::pi / 1e-3, 1e-5 * 1571.0);
  EXPECT_EQ(world.limitHits().translation, 1);
  EXPECT_EQ(world.limitHits().rotation, 1);

  const SceneDef calm = openScene({ball({0.0, 0.0}, {1999.0, 0.0})});
  Box2DWorld ok(calm, Box2DSettings::forScene(calm));
  ok.step();
  EXPECT_EQ(ok.ball(0).velocity.x(), 1999.0);
  EXPECT_EQ(ok.limitHits().translation, 0);
  EXPECT_EQ(ok.limitHits().rotation, 0);
}

}  // namespace
}  // namespace particles::reference
