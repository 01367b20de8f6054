// SolverSettings::sweptBalls: continuous collision between balls. Every
// expected figure is worked out here from the collision laws (momentum, the
// restitution law along the normal at the time of impact), not read back
// from the engine.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "particles/swept_ball.h"
#include "particles/world.h"

namespace particles {
namespace {

constexpr double kDt = 1e-3;

BallDef ball(Vec2 x, Vec2 v, double r, double m, double w = 0.0) {
  BallDef b;
  b.position = x;
  b.velocity = v;
  b.radius = r;
  b.mass = m;
  b.angularVelocity = w;
  return b;
}

SceneDef scene(std::vector<BallDef> balls, double e, double mu, bool swept) {
  SceneDef s;
  s.contact = {e, mu};
  s.balls = std::move(balls);
  s.dt = kDt;
  s.solver.sweptBalls = swept;
  return s;
}

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// (a) Equal balls, r = 0.5, closing at 2500 m/s = 5 radii per 1 ms step:
// ball 0 at x = 0 with +2000 m/s, ball 1 at x = 2 with -500 m/s. The 1 m gap
// closes at t* = 1 / 2500 = 0.4 ms. Equal masses, e = 1, head-on: they
// exchange velocities (-500 and +2000), so after the step
// x0 = 2000 t* - 500 (dt - t*) = 0.5 and x1 = 2 - 500 t* + 2000 (dt - t*) = 3.
SceneDef headOn(bool swept) {
  return scene({ball({0, 0}, {2000, 0}, 0.5, 1.0), ball({2, 0}, {-500, 0}, 0.5, 1.0)}, 1.0, 0.0,
               swept);
}

TEST(SweptBalls, WithoutTheSwitchEqualBallsAtFiveRadiiPerStepTunnel) {
  World w(headOn(false));
  w.run(10);
  EXPECT_GT(w.ball(0).position.x(), w.ball(1).position.x());
  EXPECT_EQ(w.ball(0).velocity.x(), 2000.0);
  EXPECT_EQ(w.ball(1).velocity.x(), -500.0);
}

TEST(SweptBalls, EqualBallsExchangeVelocitiesAtTheTimeOfImpact) {
  World w(headOn(true));
  w.step();
  EXPECT_NEAR(w.ball(0).velocity.x(), -500.0, 1e-9);
  EXPECT_NEAR(w.ball(1).velocity.x(), 2000.0, 1e-9);
  EXPECT_NEAR(w.ball(0).position.x(), 0.5, 1e-12);
  EXPECT_NEAR(w.ball(1).position.x(), 3.0, 1e-12);
  // Momentum (1500 kg m/s) and, for e = 1, kinetic energy (2,125,000 J).
  const double p = w.ball(0).velocity.x() + w.ball(1).velocity.x();
  const double ke = 0.5 * (w.ball(0).velocity.squaredNorm() + w.ball(1).velocity.squaredNorm());
  EXPECT_NEAR(p, 1500.0, 1e-9);
  EXPECT_NEAR(ke, 0.5 * (2000.0 * 2000.0 + 500.0 * 500.0), 1e-6);
  // They fly apart: no overlap after this step or later ones, and after n
  // steps x0 = 0.5 - 500 (n - 1) dt.
  for (int n = 2; n <= 20; ++n) {
    w.step();
    EXPECT_GE((w.ball(1).position - w.ball(0).position).norm(), 1.0);
  }
  EXPECT_NEAR(w.ball(0).position.x(), 0.5 - 500.0 * 19 * kDt, 1e-9);
  EXPECT_NEAR(w.ball(1).position.x(), 3.0 + 2000.0 * 19 * kDt, 1e-9);
}

// (b) A small fast ball (r = 0.05 m, 10 g, 250 m/s = 5 of its radii per
// step) into a heavy one (r = 1 m, 100 kg, at rest 1.2 m away), e = 0.5.
// Contact when the 1.2 - 1.05 = 0.15 m gap has closed: t* = 0.6 ms. The 1-D
// collision law: v1' = (m1 u1 - m2 e u1) / (m1 + m2), v2' = m1 (1 + e) u1 /
// (m1 + m2); positions move with u until t*, with v' after.
TEST(SweptBalls, SmallFastBallOffAHeavyBall) {
  const double m1 = 0.01, m2 = 100.0, u = 250.0, e = 0.5, ts = 0.15 / u;
  World w(scene({ball({0, 0}, {u, 0}, 0.05, m1), ball({1.2, 0}, {0, 0}, 1.0, m2)}, e, 0.0, true));
  w.step();
  const double v1 = (m1 - e * m2) * u / (m1 + m2), v2 = m1 * (1 + e) * u / (m1 + m2);
  EXPECT_NEAR(w.ball(0).velocity.x(), v1, 1e-10 * u);
  EXPECT_NEAR(w.ball(1).velocity.x(), v2, 1e-10 * u);
  EXPECT_NEAR(w.ball(0).position.x(), u * ts + v1 * (kDt - ts), 1e-12);
  EXPECT_NEAR(w.ball(1).position.x(), 1.2 + v2 * (kDt - ts), 1e-12);
  EXPECT_NEAR(m1 * w.ball(0).velocity.x() + m2 * w.ball(1).velocity.x(), m1 * u, 1e-12);
}

// (c) Grazing: ball 1 sits 1 + 1e-6 m off ball 0's line of flight, so the
// centres never come closer than 1 + 1e-6 > r1 + r2 = 1: no contact, nothing
// changes. At 1 - 1e-6 they touch and the hit deflects both.
TEST(SweptBalls, APathThatMissesByAHairDoesNotCollide) {
  for (const double offset : {1.0 + 1e-6, 1.0 - 1e-6}) {
    World w(scene({ball({0, 0}, {2500, 0}, 0.5, 1.0), ball({2, offset}, {0, 0}, 0.5, 1.0)}, 1.0,
                  0.0, true));
    w.step();
    const bool hit = offset < 1.0;
    EXPECT_EQ(w.ball(1).velocity == Vec2(0, 0), !hit) << offset;
    if (!hit) {
      EXPECT_EQ(w.ball(0).velocity, Vec2(2500, 0));
      EXPECT_EQ(w.ball(0).position, Vec2(2.5, 0));
    }
  }
}

// (d) A glancing, rough, spinning swept hit (e = 0.7, mu = 0.3). The time of
// impact solves |d + w t| = r1 + r2 (d, w: relative position and velocity);
// the impulse acts at the contact point P there, so linear momentum and the
// angular momentum about P (sum of m (x - P) x v + I omega) are the same
// before and after the step (free flight conserves both too), and the normal
// relative velocity at P is -e times what it was.
TEST(SweptBalls, GlancingHitConservesMomentumAndAngularMomentumAboutTheContact) {
  const BallDef a = ball({0, 0}, {2000, 0}, 0.5, 1.0, 30.0);
  const BallDef b = ball({1.8, 0.4}, {-500, 100}, 0.3, 2.0, -10.0);
  World w(scene({a, b}, 0.7, 0.3, true));
  const Vec2 d = b.position - a.position, v = b.velocity - a.velocity;
  const double reach = a.radius + b.radius;
  const double qa = v.squaredNorm(), qb = d.dot(v), qc = d.squaredNorm() - reach * reach;
  const double ts = (-qb - std::sqrt(qb * qb - qa * qc)) / qa;
  ASSERT_GT(ts, 0.0);
  ASSERT_LT(ts, kDt);
  const Vec2 n = (d + ts * v) / reach;
  const Vec2 P = a.position + ts * a.velocity + a.radius * n;

  auto momentum = [&](const BallState& s0, const BallState& s1) {
    return Vec2(a.mass * s0.velocity + b.mass * s1.velocity);
  };
  auto angular = [&](const BallState& s0, const BallState& s1) {
    return a.mass * cross(s0.position - P, s0.velocity) + a.resolvedInertia() * s0.angularVelocity +
           b.mass * cross(s1.position - P, s1.velocity) + b.resolvedInertia() * s1.angularVelocity;
  };
  const BallState a0 = w.ball(0), b0 = w.ball(1);
  const Vec2 p0 = momentum(a0, b0);
  const double l0 = angular(a0, b0);
  w.step();
  const BallState a1 = w.ball(0), b1 = w.ball(1);
  ASSERT_NE(a1.velocity, a.velocity) << "no hit";
  EXPECT_NEAR((momentum(a1, b1) - p0).norm(), 0.0, 1e-12 * p0.norm());
  EXPECT_NEAR(angular(a1, b1), l0, 1e-10 * std::fabs(l0));
  EXPECT_NEAR((b1.velocity - a1.velocity).dot(n), -0.7 * v.dot(n), 1e-9 * v.norm());
  EXPECT_GE((b1.position - a1.position).norm(), reach * (1 - 1e-12));
}

// (e) The grid path (60 balls > gridThreshold): a light ball (1 kg) at
// 5000 m/s = 10 radii per step crosses a row of heavy balls (1000 kg, 1.5 m
// apart, the nearest at x = 3). Within the first step its path reaches the
// nearest at t* = 2 / 5000 = 0.4 ms and the next at 0.7 ms; it must hit the
// nearest (index 59; the one behind it has the lower index 58) and bounce
// back: v1' = (1 - 1000) / 1001 * 5000, v2' = 2 / 1001 * 5000.
SceneDef row(bool swept) {
  std::vector<BallDef> balls{ball({0, 0}, {5000, 0}, 0.5, 1.0)};
  for (int k = 1; k < 60; ++k) balls.push_back(ball({3 + 1.5 * (59 - k), 0}, {0, 0}, 0.5, 1000.0));
  return scene(balls, 1.0, 0.0, swept);
}

TEST(SweptBalls, OnTheGridAFastBallHitsTheFirstBallInItsPath) {
  World w(row(true));
  ASSERT_TRUE(w.plan().grid);
  w.recordImpacts(true);
  w.step();
  const double u = 5000.0, ts = 2.0 / u;
  const double v1 = (1.0 - 1000.0) / 1001.0 * u, v2 = 2.0 / 1001.0 * u;
  EXPECT_NEAR(w.ball(0).velocity.x(), v1, 1e-10 * u);
  EXPECT_NEAR(w.ball(59).velocity.x(), v2, 1e-10 * u);
  for (int k = 1; k < 59; ++k) EXPECT_EQ(w.ball(k).velocity, Vec2(0, 0)) << k;
  EXPECT_NEAR(w.ball(0).position.x(), u * ts + v1 * (kDt - ts), 1e-12);
  ASSERT_EQ(w.impacts().size(), 1u);
  EXPECT_EQ(w.impacts()[0].a, 0);
  EXPECT_EQ(w.impacts()[0].b, 59);

  World off(row(false));
  off.step();
  EXPECT_EQ(off.ball(0).velocity.x(), u);  // not seen: it is already past the first ball
  EXPECT_GT(off.ball(0).position.x(), 3.0);
}

// The grid on swept bounds finds exactly the brute-force swept pairs, in
// the same order, among 300 balls with speeds from 0 to 200 radii per step.
TEST(SweptBalls, GridFindsTheSamePairsAsBruteForce) {
  std::uint64_t s = 11;
  auto uniform = [&] {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) * 0x1.0p-53;
  };
  std::vector<Vec2> x, v;
  std::vector<double> r;
  for (int i = 0; i < 300; ++i) {
    x.emplace_back(40 * uniform(), 40 * uniform());
    const double speed = (i % 10 == 0 ? 200.0 : 2.0) * uniform() * 0.5 / kDt;
    const double angle = 6.283185307179586 * uniform();
    v.emplace_back(speed * std::cos(angle), speed * std::sin(angle));
    r.push_back(0.2 + 0.3 * uniform());
  }
  SweptPairFinder finder;
  std::vector<SweptPair> brute, grid;
  finder.find(x, v, r, kDt, false, brute);
  finder.find(x, v, r, kDt, true, grid);
  ASSERT_GT(brute.size(), 10u);
  ASSERT_EQ(grid.size(), brute.size());
  for (std::size_t k = 0; k < brute.size(); ++k) {
    EXPECT_EQ(grid[k].a, brute[k].a);
    EXPECT_EQ(grid[k].b, brute[k].b);
    EXPECT_EQ(grid[k].time, brute[k].time);
    EXPECT_EQ(grid[k].normal, brute[k].normal);
  }
}

}  // namespace
}  // namespace particles
