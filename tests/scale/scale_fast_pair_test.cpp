// The large-scene path's rows for fast pairs (SolverSettings::
// scaleFastPairCells, docs/scale.md, "Rows for fast pairs"): a ball closing
// on another faster than the rows' margin (0.2 of the largest radius) a step
// gets a speculative row with it and bounces within the step, instead of
// landing inside it. Equal disks, radius r = 0.5 m, 1 kg, dt = 1/60 s, no
// gravity unless said, a box far from every ball.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "large_path_scene.h"
#include "particles/world.h"

namespace particles {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kR = 0.5;
constexpr double kSpeed = 60.0;  // m/s: 1 m a step, 10 times the margin
constexpr double kE = 0.5;

BallDef disk(Vec2 x, Vec2 v) {
  BallDef b;
  b.position = x;
  b.velocity = v;
  b.radius = kR;
  b.mass = 1.0;
  return b;
}

// The largest overlap between any two balls, as a fraction of the radius.
double deepestOverlap(const World& w) {
  double deepest = 0.0;
  for (std::size_t i = 0; i < w.ballCount(); ++i)
    for (std::size_t j = i + 1; j < w.ballCount(); ++j) {
      const double d = (w.ball(i).position - w.ball(j).position).norm();
      deepest = std::max(deepest, (2.0 * kR - d) / kR);
    }
  return deepest;
}

// Head-on, A at u towards B at rest, with a gap of 0.5 m (5 margins): A
// reaches B after half a step. The closed form of the handout's impact for
// equal masses along the line of centres: v_A' = u (1 - e) / 2,
// v_B' = u (1 + e) / 2, whatever mu (no tangential velocity, no spin).
SceneDef headOn(int fastPairCells) {
  SceneDef s = test::largePathScene(kDt, 0.0, {0.0, 0.0}, {20.0, 20.0});
  s.contact = {kE, 0.5};
  s.solver.scaleFastPairCells = fastPairCells;
  s.balls = {disk({5.0, 10.0}, {kSpeed, 0.0}), disk({6.5, 10.0}, {0.0, 0.0})};
  return s;
}

void expectTheClosedFormImpact(const World& w, std::size_t a, std::size_t b, double u) {
  EXPECT_NEAR(w.ball(a).velocity.x(), u * (1.0 - kE) / 2.0, 1e-12);
  EXPECT_NEAR(w.ball(b).velocity.x(), u * (1.0 + kE) / 2.0, 1e-12);
  EXPECT_EQ(w.ball(a).velocity.y(), 0.0);
  EXPECT_EQ(w.ball(b).velocity.y(), 0.0);
  EXPECT_EQ(w.ball(a).angularVelocity, 0.0);
  EXPECT_EQ(w.ball(b).angularVelocity, 0.0);
  // Momentum kept, energy lost as e says: (1 - e^2) of the relative motion's.
  EXPECT_NEAR(w.ball(a).velocity.x() + w.ball(b).velocity.x(), u, 1e-12);
  const double energy = 0.5 * (w.ball(a).velocity.squaredNorm() + w.ball(b).velocity.squaredNorm());
  EXPECT_NEAR(energy, 0.5 * u * u - 0.25 * (1.0 - kE * kE) * u * u, 1e-9);
}

TEST(ScaleFastPairs, AFastBallBouncesOffABallBeyondTheMarginWithinTheStep) {
  World w(headOn(2));
  ASSERT_TRUE(w.plan().scale);
  w.step();
  expectTheClosedFormImpact(w, 0, 1, kSpeed);
  // The bounce starts when the row is made (up to a gap early): apart.
  EXPECT_LE(deepestOverlap(w), 0.0);
  for (int k = 0; k < 30; ++k) {
    w.step();
    ASSERT_LE(deepestOverlap(w), 0.0) << "after step " << k + 2;
  }
}

// Without the longer search (the code before it) the pair has no row: A
// moves its full 1 m and ends half its diameter inside B, 100 % of the
// radius (the kind of overlap the 100,000 pile's landing balls made), with
// no impulse; the overlap removal, which works on rows, does not see it.
TEST(ScaleFastPairs, WithoutTheLongerSearchTheBallLandsInsideTheOther) {
  World w(headOn(0));
  w.step();
  EXPECT_EQ(w.ball(0).velocity.x(), kSpeed);
  EXPECT_EQ(w.ball(1).velocity.x(), 0.0);
  EXPECT_NEAR(deepestOverlap(w), 1.0, 1e-12);
}

// The pair is made by the ball that reaches further; here by the second in
// the grid's order, which its row then lists first. X at rest, Y to its
// right moving left at u, Z 2.3 m right of Y moving right at u: Z lies
// within two cells (of 1.1 m) of Y but not of X, so Y's velocity differs by
// 2u from one in its cells and by u from any in X's, and Y reaches further.
// The impact is the same closed form, mirrored.
TEST(ScaleFastPairs, ThePairOfTheFartherReachingBallIsTheSameImpact) {
  SceneDef s = test::largePathScene(kDt, 0.0, {0.0, 0.0}, {20.0, 20.0});
  s.contact = {kE, 0.5};
  s.balls = {disk({8.8, 10.0}, {kSpeed, 0.0}), disk({6.5, 10.0}, {-kSpeed, 0.0}),
             disk({5.0, 10.0}, {0.0, 0.0})};
  World w(s);
  w.step();
  // Mirrored: Y (ball 1) is A at -u, X (ball 2) is B.
  EXPECT_NEAR(w.ball(1).velocity.x(), -kSpeed * (1.0 - kE) / 2.0, 1e-12);
  EXPECT_NEAR(w.ball(2).velocity.x(), -kSpeed * (1.0 + kE) / 2.0, 1e-12);
  EXPECT_NEAR(w.ball(1).velocity.x() + w.ball(2).velocity.x(), -kSpeed, 1e-12);
  EXPECT_EQ(w.ball(0).velocity.x(), kSpeed);  // Z meets nothing
  EXPECT_LE(deepestOverlap(w), 0.0);
}

// Oblique: A at u along x, its line of motion h above B's centre (B at
// rest). For h < 2r A starts 0.5 m (half a step) before the contact
// position, so the rows are made while the balls are 1.45 m apart for h = r
// (beyond the margin: the longer search's row); for h >= 2r (a miss) B lies
// 0.3 m ahead of A along x (1.06 m apart for h = 1.02 m: within the margin,
// the plain search's row; 1.14 m for h = 1.1 m: the longer search's).
SceneDef oblique(double h, double mu) {
  SceneDef s = test::largePathScene(kDt, 0.0, {0.0, 0.0}, {40.0, 20.0});
  s.contact = {kE, mu};
  // x of B from A at contact
  const double reachX = h < 2.0 * kR ? std::sqrt(4.0 * kR * kR - h * h) : -0.2;
  s.balls = {disk({10.0, 10.0 + h}, {kSpeed, 0.0}), disk({10.0 + reachX + 0.5, 10.0}, {0.0, 0.0})};
  return s;
}

// The contact normal of that impact, from A to B at the moment they touch:
// (sqrt(4r^2 - h^2), -h) / 2r. Geometry alone, not the solver's arithmetic.
Vec2 obliqueNormal(double h) {
  return Vec2(std::sqrt(4.0 * kR * kR - h * h), -h) / (2.0 * kR);
}

// Smooth (mu = 0), h = r: the impulse lies along the contact normal n, not
// along the start's line of centres (which is 9.9 degrees off it), and is the
// closed form for equal masses: B leaves along n at (1 + e) u n_x / 2, A keeps
// the rest, no spin.
TEST(ScaleFastPairs, AFastObliqueHitTakesTheImpulseAlongTheContactNormal) {
  const double h = kR;
  World w(oblique(h, 0.0));
  ASSERT_TRUE(w.plan().scale);
  w.step();
  const Vec2 n = obliqueNormal(h);
  const Vec2 u(kSpeed, 0.0);
  const Vec2 vb = 0.5 * (1.0 + kE) * u.dot(n) * n;
  EXPECT_NEAR(w.ball(1).velocity.x(), vb.x(), 1e-9);
  EXPECT_NEAR(w.ball(1).velocity.y(), vb.y(), 1e-9);
  EXPECT_NEAR(w.ball(0).velocity.x(), u.x() - vb.x(), 1e-9);
  EXPECT_NEAR(w.ball(0).velocity.y(), u.y() - vb.y(), 1e-9);
  EXPECT_EQ(w.ball(0).angularVelocity, 0.0);
  EXPECT_EQ(w.ball(1).angularVelocity, 0.0);
  EXPECT_LE(deepestOverlap(w), 0.0);
}

// With friction, h = r again: stopping the contact points' slip, u sin(30
// deg) = 30 m/s, takes |lambda_t| = 30 / (2/m + 2 r^2/J) = 5 N s, within mu
// times the normal impulse of the plastic part alone (0.5 * u n_x / 2 = 13
// N s), so the impact sticks: the contact points leave with the same
// tangential velocity (the no-slip condition), the normal relative velocity
// is e u n_x, B takes 5 N s along the tangent, and each ball keeps its
// angular momentum about the contact point (the impulse acts there).
TEST(ScaleFastPairs, AFastObliqueHitWithFrictionSticksAsTheClosedFormSays) {
  const double h = kR, mu = 0.5;
  World w(oblique(h, mu));
  const BallState a0 = w.ball(0);
  w.step();
  const BallState& a = w.ball(0);
  const BallState& b = w.ball(1);
  const Vec2 n = obliqueNormal(h);
  const Vec2 tau(-n.y(), n.x());
  const Vec2 u(kSpeed, 0.0);
  // Velocities of the contact points: v + omega x (arm), arms +r n and -r n.
  const Vec2 pa = a.velocity + a.angularVelocity * kR * tau;
  const Vec2 pb = b.velocity - b.angularVelocity * kR * tau;
  EXPECT_NEAR((pb - pa).dot(tau), 0.0, 1e-9);
  EXPECT_NEAR((b.velocity - a.velocity).dot(n), kE * u.dot(n), 1e-9);
  EXPECT_NEAR(std::fabs(b.velocity.dot(tau)), std::fabs(u.dot(tau)) / 6.0, 1e-9);
  EXPECT_NEAR(a.velocity.x() + b.velocity.x(), u.x(), 1e-9);
  EXPECT_NEAR(a.velocity.y() + b.velocity.y(), 0.0, 1e-9);
  // About the contact point P (at the moment of contact), L = m (x - P) x v
  // + J omega; with x - P = -r n for A, only the tangential velocity counts.
  const double J = 0.5 * kR * kR;
  const auto cross = [](const Vec2& p, const Vec2& q) { return p.x() * q.y() - p.y() * q.x(); };
  EXPECT_NEAR(cross(-kR * n, a.velocity) + J * a.angularVelocity,
              cross(-kR * n, a0.velocity) + J * a0.angularVelocity, 1e-9);
  EXPECT_NEAR(cross(kR * n, b.velocity) + J * b.angularVelocity, 0.0, 1e-9);
  EXPECT_NE(a.angularVelocity, 0.0);
}

// A fast ball passing another without touching it keeps its velocity to the
// bit, 0.1 m clear (a row of the longer search) and 0.02 m clear (a row of
// the plain search): each row lies along the line of centres at the closest
// approach and asks for nothing.
// Before the rows met where the relative motion does, the rows along the
// line of centres at the start pushed the pair apart: the ball 0.1 m clear
// left at (55.1, 10.9) m/s, the one 0.02 m clear at (53.3, 11.3) m/s.
TEST(ScaleFastPairs, AFastBallPassingAnotherIsNotDeflected) {
  for (const double clear : {0.1, 0.02}) {
    World w(oblique(2.0 * kR + clear, 0.5));
    for (int k = 0; k < 6; ++k) w.step();
    EXPECT_EQ(w.ball(0).velocity.x(), kSpeed) << clear;
    EXPECT_EQ(w.ball(0).velocity.y(), 0.0) << clear;
    EXPECT_EQ(w.ball(1).velocity.squaredNorm(), 0.0) << clear;
    EXPECT_EQ(w.ball(0).angularVelocity, 0.0) << clear;
  }
}

// Under gravity, a ball falling at 50 m/s onto a stack of three on the floor,
// 0.6 m above the top one: no overlap deeper than the 5 % of the issue's
// target at any step while it lands and the stack settles, and no ball gains
// energy from the landing (the stack ends below its falling ball's energy).
TEST(ScaleFastPairs, ABallFallingFastOntoAStackDoesNotSinkIntoIt) {
  SceneDef s = test::largePathScene(kDt, 10.0, {-5.0, 0.0}, {5.0, 40.0});
  s.contact = {kE, 0.5};
  test::addStack(s, 0.0, 3, kR);
  s.balls.push_back(disk({0.0, 5.0 * kR + 2.0 * kR + 0.6}, {0.0, -50.0}));
  World w(s);
  const double before = 0.5 * 50.0 * 50.0 + 10.0 * (5.0 * kR + 2.0 * kR + 0.6);
  for (int k = 0; k < 120; ++k) {
    w.step();
    ASSERT_LE(deepestOverlap(w), 0.05) << "after step " << k + 1;
  }
  double energy = 0.0;
  for (std::size_t i = 0; i < w.ballCount(); ++i)
    energy += 0.5 * w.ball(i).velocity.squaredNorm() + 10.0 * w.ball(i).position.y();
  EXPECT_LT(energy, before + 10.0 * (kR + 3.0 * kR + 5.0 * kR));
}

}  // namespace
}  // namespace particles
