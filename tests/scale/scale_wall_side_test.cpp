// The large-scene path and balls fast enough to cross a box wall's line
// within one step: the 100,000 pile threw balls out through the walls this
// way (docs/scale.md, "Walls with a side"). Box [0, 10]^2, no gravity,
// e = 0.5, mu = 0.5, a ball of radius r = 0.5 moving at u = 60 m/s towards
// the left wall, dt = 1/60 s (u dt = 1 m = 2 r).
#include <gtest/gtest.h>

#include <cmath>

#include "large_path_scene.h"
#include "particles/world.h"

namespace particles {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kSpeed = 60.0;  // m/s
constexpr double kE = 0.5;

SceneDef ballAtTheLeftWall(double x, bool oneSided) {
  SceneDef s = test::largePathScene(kDt, 0.0, {0.0, 0.0}, {10.0, 10.0});
  s.contact = {kE, 0.5};
  for (WallDef& w : s.walls) w.oneSided = oneSided;
  BallDef b;
  b.position = {x, 5.0};
  b.velocity = {-kSpeed, 0.0};
  b.radius = 0.5;
  s.balls = {b};
  return s;
}

// At x = 0.8 its gap to the wall, 0.3 m, is more than the rows' margin
// (0.2 r = 0.1 m): no row with the wall. The wall guard sweeps it: it meets
// the wall at t = 0.3 / u = 0.005 s, bounces to +e u = 30 m/s and moves on
// for dt - t: x = 0.5 + 30 (1/60 - 0.005) = 0.85 m. Head-on: no spin.
TEST(ScaleWallSide, AFastBallWithoutAWallRowBouncesAtItsTimeOfImpact) {
  World w(ballAtTheLeftWall(0.8, true));
  w.step();
  EXPECT_NEAR(w.ball(0).position.x(), 0.5 + kE * kSpeed * (kDt - 0.3 / kSpeed), 1e-12);
  EXPECT_NEAR(w.ball(0).position.y(), 5.0, 1e-12);
  EXPECT_NEAR(w.ball(0).velocity.x(), kE * kSpeed, 1e-12);
  EXPECT_NEAR(w.ball(0).velocity.y(), 0.0, 1e-12);
  EXPECT_EQ(w.ball(0).angularVelocity, 0.0);
}

// The same ball moving obliquely, (-u, w) with w = 20 m/s along the wall and
// no spin, with no wall row: the guard's impact is the handout's wall impact,
// worked out here for a uniform disk (m = 1 kg, J = m r^2 / 2). Normal
// impulse on the ball P_n = m (1 + e) u = 90 N s along +x. The contact point
// (-r, 0) from the centre slips along +y at w - omega r = 20 m/s; a
// tangential impulse P_t changes that slip by P_t (1/m + r^2/J) = 3 P_t / m,
// so no-slip needs P_t = -20/3 N s, within mu P_n when mu = 0.5 (sticks)
// and clamped to -mu P_n = -4.5 N s when mu = 0.05 (slides). Then
// v_y' = w + P_t / m and omega' = -r P_t / J (the torque of P_t about the
// centre). Angular momentum about the contact point, J omega + m r v_y, is
// the same before and after: the impulse acts at that point.
struct ObliqueGuardCase {
  double friction;
  double tangentImpulse;  // N s, P_t worked out above
};

void expectTheHandoutsWallImpact(const ObliqueGuardCase& c) {
  constexpr double kAlong = 20.0;  // m/s
  constexpr double kR = 0.5, kMass = 1.0, kJ = kMass * kR * kR / 2.0;
  SceneDef scene = ballAtTheLeftWall(0.8, true);
  scene.contact = {kE, c.friction};
  scene.balls[0].velocity = {-kSpeed, kAlong};
  World w(scene);
  w.step();
  const BallState b = w.ball(0);
  const double vy = kAlong + c.tangentImpulse / kMass;
  const double omega = -kR * c.tangentImpulse / kJ;
  const double impact = 0.3 / kSpeed;  // s, time of impact
  EXPECT_NEAR(b.velocity.x(), kE * kSpeed, 1e-12);
  EXPECT_NEAR(b.velocity.y(), vy, 1e-12);
  EXPECT_NEAR(b.angularVelocity, omega, 1e-12);
  EXPECT_NEAR(b.position.x(), 0.5 + kE * kSpeed * (kDt - impact), 1e-12);
  EXPECT_NEAR(b.position.y(), 5.0 + kAlong * impact + vy * (kDt - impact), 1e-12);
  // Invariants, whatever the regime: angular momentum about the contact
  // point kept, the Coulomb bound |P_t| <= mu P_n, kinetic energy not grown.
  EXPECT_NEAR(kJ * b.angularVelocity + kMass * kR * b.velocity.y(), kMass * kR * kAlong, 1e-12);
  const double normalImpulse = kMass * (b.velocity.x() + kSpeed);
  const double tangentImpulse = kMass * (b.velocity.y() - kAlong);
  EXPECT_LE(std::abs(tangentImpulse), c.friction * normalImpulse * (1.0 + 1e-12));
  const double before = 0.5 * kMass * (kSpeed * kSpeed + kAlong * kAlong);
  const double after =
      0.5 * kMass * b.velocity.squaredNorm() + 0.5 * kJ * b.angularVelocity * b.angularVelocity;
  EXPECT_LT(after, before);
}

TEST(ScaleWallSide, AnObliqueFastBallSticksLikeAnyWallImpact) {
  expectTheHandoutsWallImpact({0.5, -20.0 / 3.0});
}

TEST(ScaleWallSide, AnObliqueFastBallSlidesWhenFrictionIsTooWeak) {
  expectTheHandoutsWallImpact({0.05, -0.05 * (1.0 + kE) * kSpeed});
}

// Centre 0.2 m past the left wall's line (as a ball pressed through by its
// neighbours' overlap removal can be). One-sided (boxWalls): it touches the
// wall from behind, normal (-1, 0) towards the wall, approaching at u: the
// row bounces it to +e u, it moves to -0.2 + 0.5 = 0.3 m and the overlap
// removal puts it at x = r = 0.5 m, inside.
TEST(ScaleWallSide, ABallBehindABoxWallComesBackIn) {
  World w(ballAtTheLeftWall(-0.2, true));
  w.step();
  EXPECT_NEAR(w.ball(0).position.x(), 0.5, 1e-12);
  EXPECT_NEAR(w.ball(0).velocity.x(), kE * kSpeed, 1e-12);
  EXPECT_NEAR(w.ball(0).velocity.y(), 0.0, 1e-12);
  EXPECT_NEAR(w.ball(0).angularVelocity, 0.0, 1e-12);
}

// Two-sided: it touches the wall on its far side, normal (1, 0), and is
// leaving along it: no impulse; it moves on to -0.2 - u dt = -1.2 m, out.
TEST(ScaleWallSide, ATwoSidedWallLetsItOut) {
  World w(ballAtTheLeftWall(-0.2, false));
  w.step();
  EXPECT_NEAR(w.ball(0).position.x(), -1.2, 1e-12);
  EXPECT_EQ(w.ball(0).velocity.x(), -kSpeed);
}

// However long the fast ball bounces between the walls, every step ends
// with its centre at least r inside both (up to the overlap removal's
// tolerance, 1e-9 of the reach), and its speed never grows (e < 1).
TEST(ScaleWallSide, TheBallStaysInTheBox) {
  World w(ballAtTheLeftWall(0.8, true));
  double speed = kSpeed;
  for (int k = 0; k < 600; ++k) {
    w.step();
    const double x = w.ball(0).position.x();
    ASSERT_GE(x, 0.5 - 1e-9) << "after step " << k + 1;
    ASSERT_LE(x, 9.5 + 1e-9) << "after step " << k + 1;
    ASSERT_LE(w.ball(0).velocity.norm(), speed * (1.0 + 1e-12)) << "after step " << k + 1;
    speed = w.ball(0).velocity.norm();
  }
}

// A ball the solve leaves on a wall moving into it. U, radius 0.5, touches
// the left wall (x = 0.5) and rests on L, on the floor, with the line of
// centres 30 degrees below horizontal; U falls at u. The support sweep runs
// after the wall rows and pushes U away from L along the line of centres,
// up and to the left, into the wall. Before the wall guard took a ball that
// starts on a wall, U left the solve at u = 60 moving at (-4.27, -15.97) m/s,
// into the wall, and the move carried it 0.07 m through (the overlap passes
// put it back); at 60 m/s into a wall a ball crosses its line within a step.
// Now it takes the wall's impact before it moves: with e = 0 it ends the
// step not moving into any wall it touches, and inside the box. At u = 200 it
// reaches the floor within the step and is in the corner: the floor's
// impact and friction, then the wall's, each leave it leaving that wall.
void expectNoBallEndsMovingIntoAWall(double u) {
  SceneDef s = test::largePathScene(kDt, 10.0, {0.0, 0.0}, {10.0, 10.0});
  s.contact = {0.0, 0.5};
  const double angle = M_PI / 6.0, r = 0.5;
  BallDef lower, upper;
  lower.position = {r + 2.0 * r * std::cos(angle), r};
  upper.position = {r, r + 2.0 * r * std::sin(angle)};
  lower.radius = upper.radius = r;
  upper.velocity = {0.0, -u};
  s.balls = {lower, upper};
  World w(s);
  w.step();
  const BallState b = w.ball(1);
  constexpr double kTol = 1e-9;  // the overlap removal's tolerance
  EXPECT_GE(b.position.x(), r - kTol);
  EXPECT_GE(b.position.y(), r - kTol);
  // Touching the left wall (it does, within the tolerance): not moving into it.
  ASSERT_LE(b.position.x(), r + kTol);
  EXPECT_GE(b.velocity.x(), -1e-12);
  if (b.position.y() <= r + kTol) {
    EXPECT_GE(b.velocity.y(), -1e-12);  // and the floor, in the corner
  }
}

TEST(ScaleWallSide, TheSupportSweepCannotDriveABallOnAWallIntoIt) {
  expectNoBallEndsMovingIntoAWall(60.0);
}

TEST(ScaleWallSide, ABallDrivenIntoACornerLeavesBothWalls) {
  expectNoBallEndsMovingIntoAWall(200.0);
}

}  // namespace
}  // namespace particles
