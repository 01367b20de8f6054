// The large-scene path's impulses checked against the closed forms of
// docs/physics.md, on scenes forced onto the path (scaleThreshold = 0): a
// head-on impact of two equal balls, a sliding hit on a floor (Coulomb
// clamp, spin sign), and a ball resting on a floor under gravity.
#include <gtest/gtest.h>

#include "particles/world.h"

namespace particles {
namespace {

SceneDef onScalePath() {
  SceneDef s;
  s.dt = 1e-3;
  s.solver.scaleThreshold = 0;  // every scene takes the large-scene path
  return s;
}

BallDef ball(const Vec2& x, const Vec2& v, double r = 0.5, double m = 1.0) {
  BallDef b;
  b.position = x;
  b.velocity = v;
  b.radius = r;
  b.mass = m;
  return b;
}

// Equal masses, smooth, e: the velocities leave as -e times the approach,
// shared equally (v1' = -e u, v2' = e u for u and -u).
TEST(ScaleImpact, HeadOnMatchesTheClosedForm) {
  SceneDef s = onScalePath();
  s.contact = {0.6, 0.0};
  s.balls = {ball({0.0, 0.0}, {2.0, 0.0}), ball({1.0, 0.0}, {-2.0, 0.0})};
  World w(s);
  ASSERT_TRUE(w.plan().scale);
  w.step();
  EXPECT_NEAR(w.ball(0).velocity.x(), -0.6 * 2.0, 1e-12);
  EXPECT_NEAR(w.ball(1).velocity.x(), 0.6 * 2.0, 1e-12);
  EXPECT_EQ(w.ball(0).velocity.y(), 0.0);
  EXPECT_NEAR(w.ball(0).velocity.x() + w.ball(1).velocity.x(), 0.0, 1e-12);  // momentum
}

// A disk hits a floor at (1, -2) m/s without spin, mu = 0.1, e = 0.5 (r = 0.5,
// q = J / (m r^2) = 1/2): sliding, so v_x' = v_x - mu (1 + e) |v_y| = 0.7,
// v_y' = e |v_y| = 1, w' = -mu (1 + e) |v_y| / (q r) = -1.2 rad/s. The disk's
// centre starts `gap` (m) above touching height.
void expectSlidingFloorHit(double gap) {
  SceneDef s = onScalePath();
  s.contact = {0.5, 0.1};
  s.walls = boxWalls({-10.0, 0.0}, {10.0, 10.0});
  s.balls = {ball({0.0, 0.5 + gap}, {1.0, -2.0})};
  World w(s);
  w.step();
  EXPECT_NEAR(w.ball(0).velocity.x(), 0.7, 1e-12);
  EXPECT_NEAR(w.ball(0).velocity.y(), 1.0, 1e-12);
  EXPECT_NEAR(w.ball(0).angularVelocity, -1.2, 1e-12);
}

TEST(ScaleImpact, SlidingFloorHitMatchesTheClosedForm) {
  expectSlidingFloorHit(0.0);
}

// Two equal disks (1 kg, r = 0.5, J = m r^2 / 2), mu = 0.1, e = 0.5: A at
// (2, 1) m/s hits B at rest along x. The normal impulse is (1 + e) u m / 2 =
// 1.5 N s for the approach u = 2 m/s. Stopping the slip of the contact points
// (1 m/s) would take 1 / (2/m + 2 r^2/J) = 1/6 N s > mu 1.5 = 0.15, so the
// disks slide: 0.15 N s along y. A leaves at (0.5, 0.85), B at (1.5, 0.15), both
// spinning at -0.15 r / J = -0.6 rad/s. The iterations before the last
// over-relax the normal impulse (SolverSettings::scaleOverRelaxation), which
// overshoots; the last one sets it exactly before the friction takes its
// bound, so the friction is not clamped by an overshot impulse.
void expectObliqueSlidingHit(const World& w) {
  EXPECT_NEAR(w.ball(0).velocity.x(), 0.5, 1e-12);
  EXPECT_NEAR(w.ball(0).velocity.y(), 0.85, 1e-12);
  EXPECT_NEAR(w.ball(1).velocity.x(), 1.5, 1e-12);
  EXPECT_NEAR(w.ball(1).velocity.y(), 0.15, 1e-12);
  EXPECT_NEAR(w.ball(0).angularVelocity, -0.6, 1e-12);
  EXPECT_NEAR(w.ball(1).angularVelocity, -0.6, 1e-12);
}

// That hit, solved on the large path with the default over-relaxation.
TEST(ScaleImpact, ObliqueSlidingHitOfTwoBallsMatchesTheClosedForm) {
  SceneDef s = onScalePath();
  s.contact = {0.5, 0.1};
  s.balls = {ball({0.0, 0.0}, {2.0, 1.0}), ball({1.0, 0.0}, {0.0, 0.0})};
  World w(s);
  ASSERT_TRUE(w.plan().scale);
  ASSERT_GT(s.solver.scaleOverRelaxation, 1.0);
  w.step();
  expectObliqueSlidingHit(w);
}

// The same hit caught before contact: B starts 1 mm away and A closes 2 mm
// in the step (dt = 1 ms), so the row is speculative. Its passes push only
// what closes the gap and the restitution pass adds the bounce; the friction
// must still end bounded by mu times the whole 1.5 N s, as in Walton's law,
// not by mu times the passes' part of it, the 0.5 N s that closes the gap
// (which gave 0.05 N s of friction here before the restitution pass updated
// the friction: docs/scale.md, "The rough gas").
TEST(ScaleImpact, ObliqueSlidingHitCaughtBeforeContactMatchesTheClosedForm) {
  SceneDef s = onScalePath();
  s.contact = {0.5, 0.1};
  s.balls = {ball({0.0, 0.0}, {2.0, 1.0}), ball({1.001, 0.0}, {0.0, 0.0})};
  World w(s);
  w.recordImpacts(true);
  w.step();
  ASSERT_EQ(w.impacts().size(), 1u);
  EXPECT_NEAR(w.impacts()[0].normalImpulse, 1.5, 1e-12);
  expectObliqueSlidingHit(w);
}

// The sliding floor hit above, caught 1 mm before contact.
TEST(ScaleImpact, SlidingFloorHitCaughtBeforeContactMatchesTheClosedForm) {
  expectSlidingFloorHit(0.001);
}

// No-slip (mu = infinity) and the oblique hit caught before contact: the
// contact points leave with equal tangential velocities. Stopping the slip
// of 1 m/s takes 1/6 N s along y (M_t = 1 / (2/m + 2 r^2/J) = 1/6 kg): A
// leaves at (0.5, 5/6), B at (1.5, 1/6), both spinning at
// -(1/6) r / J = -2/3 rad/s; the slip (vB - vA).y - wB r - wA r is then 0.
TEST(ScaleImpact, NoSlipHitCaughtBeforeContactSticks) {
  SceneDef s = onScalePath();
  s.contact = {0.5, kNoSlip};
  s.balls = {ball({0.0, 0.0}, {2.0, 1.0}), ball({1.001, 0.0}, {0.0, 0.0})};
  World w(s);
  w.step();
  EXPECT_NEAR(w.ball(0).velocity.x(), 0.5, 1e-12);
  EXPECT_NEAR(w.ball(0).velocity.y(), 5.0 / 6.0, 1e-12);
  EXPECT_NEAR(w.ball(1).velocity.x(), 1.5, 1e-12);
  EXPECT_NEAR(w.ball(1).velocity.y(), 1.0 / 6.0, 1e-12);
  EXPECT_NEAR(w.ball(0).angularVelocity, -2.0 / 3.0, 1e-12);
  EXPECT_NEAR(w.ball(1).angularVelocity, -2.0 / 3.0, 1e-12);
}

// The same hit with a material per ball, mixed by Box2D's rules (docs/physics.md):
// e = max(0.5, 0.2) = 0.5 and mu = sqrt(0.04 * 0.25) = 0.1, so the closed form
// above holds. A scene whose balls share one material mixes it once per step;
// this one takes the per-row mix.
TEST(ScaleImpact, MaterialsPerBallAreMixedPerRow) {
  SceneDef s = onScalePath();
  s.balls = {ball({0.0, 0.0}, {2.0, 1.0}), ball({1.0, 0.0}, {0.0, 0.0})};
  s.balls[0].restitution = 0.5;
  s.balls[0].friction = 0.04;
  s.balls[1].restitution = 0.2;
  s.balls[1].friction = 0.25;
  World w(s);
  ASSERT_TRUE(w.plan().scale);
  w.step();
  expectObliqueSlidingHit(w);
}

// A constant force F on A pushes it into B, which touches it; no gravity,
// e = 1. What the force adds within a step is carried, not bounced
// (docs/physics.md): the two move as one, at F t / (m_A + m_B), and keep
// touching. Bouncing the push would send B off at twice A's speed. A scene
// whose balls all get the same push (gravity alone) skips this per-row term;
// this one needs it.
TEST(ScaleImpact, APushIsCarriedNotBounced) {
  SceneDef s = onScalePath();
  s.contact = {1.0, 0.0};
  s.balls = {ball({0.0, 0.0}, {0.0, 0.0}), ball({1.0, 0.0}, {0.0, 0.0})};
  ForceDef push;
  push.type = ForceType::Constant;
  push.ball = 0;
  push.force = {10.0, 0.0};
  s.forces = {push};
  World w(s);
  ASSERT_TRUE(w.plan().scale);
  for (int k = 1; k <= 100; ++k) {
    w.step();
    const double v = 10.0 * k * s.dt / 2.0;
    ASSERT_NEAR(w.ball(0).velocity.x(), v, 1e-12) << "step " << k;
    ASSERT_NEAR(w.ball(1).velocity.x(), v, 1e-12) << "step " << k;
  }
  EXPECT_NEAR(w.ball(1).position.x() - w.ball(0).position.x(), 1.0, 1e-9);
}

// At rest on a floor under gravity: the floor's impulse is the weight's, m g
// dt, every step; the ball neither sinks nor hops.
TEST(ScaleImpact, RestingBallStaysAtRest) {
  SceneDef s = onScalePath();
  s.gravity = {0.0, -10.0};
  s.contact = {0.5, 0.5};
  s.walls = boxWalls({-10.0, 0.0}, {10.0, 10.0});
  s.balls = {ball({0.0, 0.5}, {0.0, 0.0}, 0.5, 2.0)};
  World w(s);
  w.recordImpacts(true);
  for (int k = 0; k < 100; ++k) {
    w.step();
    ASSERT_EQ(w.impacts().size(), 1u);
    EXPECT_NEAR(w.impacts()[0].normalImpulse, 2.0 * 10.0 * 1e-3, 1e-15);
  }
  EXPECT_NEAR(w.ball(0).velocity.norm(), 0.0, 1e-15);
  EXPECT_NEAR(w.ball(0).position.y(), 0.5, 1e-12);
}

}  // namespace
}  // namespace particles
