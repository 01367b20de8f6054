// A wall is the limit of a ball that is infinitely heavy and infinitely hard
// to spin: the engine's wall (a ContactBody with zero inverse mass and
// inertia, lever arm 0, at rest) must give what a ball of mass M = 1e12 kg
// (inertia J_b = q_b M r_b^2) at rest gives, up to the size of 1/M.
//
// Tolerance, worked out by hand. Let eps = m_a / M. The normal impulse is
// -(1 + e) g_n / K_n with K_n = 1/m_a (wall) or 1/m_a + 1/M (heavy ball):
// relative difference <= eps. The no-slip tangential impulse is -g_t / K_t,
// K_t = 1/m_a + r_a^2/J_a (wall) or that plus 1/M + r_b^2/J_b
// = (1 + 1/q_b)/M (heavy ball); since K_t >= 1/m_a the relative difference
// is <= delta = (1 + 1/q_b) eps. The Coulomb bound mu lambda_n moves by <= eps,
// and where the two runs fall on different sides of the bound, both results
// lie between the two no-slip impulses (or bounds), so |d lambda| <= delta
// |lambda| in every regime. Ball a's velocity changes by P/m_a and its spin by
// r_a lambda_t / J_a, so they differ by at most delta times those changes.
// Rounding (kRoundingRel of the speeds) comes on top.
#include <gtest/gtest.h>

#include <cmath>

#include "particles/world.h"
#include "physics_test_support.h"

namespace {

using namespace physics_test;
using particles::ContactMaterial;
using particles::kNoSlip;

constexpr double kHeavyMass = 1e12;  // kg
constexpr std::uint64_t kSeed = 0x5eed'0006;

TEST(WallLimit, WallEqualsHeavyBallThroughResolveImpact) {
  ImpactGenerator gen(kSeed);
  Worst worst("wall vs 1e12 kg ball: difference / (delta * impulse velocity)");
  int compared = 0;
  for (Friction mode : kAllModes) {
    for (int i = 0; i < kCasesPerMode; ++i) {
      ImpactCase k = gen.next(mode);
      // Ball a must approach a body at rest: v_a . n > 0.
      if (std::abs(k.a.v.dot(k.n)) < 0.01) continue;
      if (k.a.v.dot(k.n) < 0.0) k.a.v -= 2.0 * k.a.v.dot(k.n) * k.n;
      const double qb = k.b.J / (k.b.m * k.b.r * k.b.r);
      Ball heavy{k.b.x, Vec2(0.0, 0.0), 0.0, kHeavyMass, k.b.r, qb * kHeavyMass * k.b.r * k.b.r};

      particles::ContactBody a1 = contactBody(k.a), wall = wallBody();
      const particles::ContactImpulse pw = particles::resolveImpact(a1, wall, k.n, k.material);
      particles::ContactBody a2 = contactBody(k.a), big = contactBody(heavy);
      const particles::ContactImpulse pb = particles::resolveImpact(a2, big, k.n, k.material);

      const double delta = (1.0 + 1.0 / qb) * k.a.m / kHeavyMass;
      const double dv = std::hypot(pw.normal, pw.tangent) / k.a.m;  // a's velocity change
      const double dw = k.a.r * std::abs(pw.tangent) / k.a.J;       // a's spin change
      const double round = kRoundingRel * (speedScale(k.a, heavy) + a1.velocity.norm() +
                                           std::abs(a1.angularVelocity) * k.a.r);
      const double velDiff = (a1.velocity - a2.velocity).norm();
      const double spinDiff = std::abs(a1.angularVelocity - a2.angularVelocity);
      EXPECT_LE(velDiff, delta * dv + round) << k.describe();
      EXPECT_LE(spinDiff, delta * dw + round / k.a.r) << k.describe();
      EXPECT_LE(std::abs(pw.normal - pb.normal), delta * std::abs(pw.normal) + round * k.a.m)
          << k.describe();
      EXPECT_LE(std::abs(pw.tangent - pb.tangent), delta * std::abs(pw.tangent) + round * k.a.m)
          << k.describe();
      if (dv > 0.0) worst.add(velDiff / (delta * dv), k.index);
      // The wall stays put; the heavy ball barely moves: v_b' = P / M.
      EXPECT_EQ(wall.velocity, Vec2(0.0, 0.0));
      EXPECT_EQ(wall.angularVelocity, 0.0);
      EXPECT_LE(big.velocity.norm(), std::hypot(pb.normal, pb.tangent) / kHeavyMass * 1.000001)
          << k.describe();
      ++compared;
      if (::testing::Test::HasFailure()) return;
    }
  }
  EXPECT_GT(compared, 14000);
}

// The same through the World: a ball hitting a floor segment y = 0 at x = 0,
// versus the same ball hitting a ball of mass 1e12 kg and radius 2 whose top
// is at the origin (its centre at (0, -2), so the normal is (0, -1) exactly
// as for the floor). No gravity (it would pull the heavy ball too); 20 steps:
// the impact in the first, then free flight.
struct FloorShot {
  Vec2 v;
  double w, e, mu;
};

particles::SceneDef shotScene(const FloorShot& s, bool wall) {
  particles::SceneDef scene;
  scene.contact = ContactMaterial{s.e, s.mu};
  scene.dt = 1e-3;
  particles::BallDef ball;
  ball.radius = 0.5;
  ball.mass = 1.5;
  ball.position = Vec2(0.0, 0.5);  // touching y = 0 (and the heavy ball's top)
  ball.velocity = s.v;
  ball.angularVelocity = s.w;
  scene.balls.push_back(ball);
  if (wall) {
    particles::WallDef floor;
    floor.a = Vec2(-10.0, 0.0);
    floor.b = Vec2(10.0, 0.0);
    scene.walls.push_back(floor);
  } else {
    particles::BallDef heavy;
    heavy.radius = 2.0;
    heavy.mass = kHeavyMass;  // inertia unset: M R^2 / 2, q_b = 1/2
    heavy.position = Vec2(0.0, -2.0);
    scene.balls.push_back(heavy);
  }
  return scene;
}

TEST(WallLimit, WallEqualsHeavyBallThroughWorld) {
  const FloorShot shots[] = {
      {Vec2(1.5, -2.0), 3.0, 0.6, kNoSlip}, {Vec2(1.5, -2.0), 3.0, 0.6, 0.4},
      {Vec2(1.5, -2.0), 3.0, 0.6, 0.05},    {Vec2(-0.7, -4.0), -9.0, 1.0, 0.0},
      {Vec2(2.0, -1.0), 0.0, 0.0, kNoSlip},
  };
  constexpr int kSteps = 20;
  for (const FloorShot& s : shots) {
    particles::World withWall(shotScene(s, true));
    particles::World withBall(shotScene(s, false));
    withWall.step();
    withBall.step();
    EXPECT_EQ(withWall.stats().contacts, 1);
    EXPECT_EQ(withBall.stats().contacts, 1);
    withWall.run(kSteps - 1);
    withBall.run(kSteps - 1);
    const particles::BallState a = withWall.ball(0), b = withBall.ball(0);
    // delta = (1 + 1/q_b) m/M = 3 * 1.5e-12. The impact changes v by at most
    // (1 + e)|v_y| + |v_x + w r| <= 2 speed, and r w by |lambda_t|/(q m)
    // = 2 |lambda_t|/m <= 4 speed (q = 1/2): 4 speed bounds both. Positions
    // integrate the velocity difference over kSteps steps.
    const double delta = 3.0 * 1.5 / kHeavyMass;
    const double speed = s.v.norm() + std::abs(s.w) * 0.5;
    const double velTol = (delta + kRoundingRel) * 4.0 * speed;
    const double posTol = kSteps * withWall.dt() * velTol + kRoundingRel;
    EXPECT_LE((a.velocity - b.velocity).norm(), velTol) << "e=" << s.e << " mu=" << s.mu;
    EXPECT_LE(std::abs(a.angularVelocity - b.angularVelocity) * 0.5, velTol)
        << "e=" << s.e << " mu=" << s.mu;
    EXPECT_LE((a.position - b.position).norm(), posTol) << "e=" << s.e << " mu=" << s.mu;
    EXPECT_LE(std::abs(a.angle - b.angle) * 0.5, posTol) << "e=" << s.e << " mu=" << s.mu;
    // The ball did bounce (not vacuous): its normal velocity is now +e |v_y|.
    EXPECT_NEAR(a.velocity.y(), -s.e * s.v.y(), kRoundingRel * speed);
  }
}

}  // namespace
