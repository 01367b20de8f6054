// An oblique impact of a ball on a floor, against formulas worked out by hand,
// through resolveImpact (ball = body a, wall = body b) and through the World
// (a ball at exact contact with a floor segment, one step, no gravity).
//
// Derivation. Ball: mass m, radius r, J = q m r^2, velocity (v_x, v_y) with
// v_y < 0, spin w. Floor y = 0 below it; n = (0, -1) from ball to wall,
// tau = z x n = (1, 0). The floor pushes the ball at its lowest point
// p = x + (0, -r) with an impulse (F, N):
//   dv = (F, N) / m,
//   dw = ((p - x) x (F, N)) / J = ((0)(N) - (-r)(F)) / J = r F / J = F / (q m r).
// Normal: restitution asks v_y' = -e v_y, so N = (1 + e) m |v_y|.
// Slip of the contact point, u = v_x + w (z x (0, -r))_x = v_x + w r; after
// the impulse u' = u + F/m + r F/(q m r) = u + F (1 + q)/(q m).
// No slip (u' = 0): F* = -q m u / (1 + q), so
//   v_x' = v_x - q u/(1 + q) = (v_x - q w r)/(1 + q),
//   w'   = w + F*/(q m r)   = w - (v_x + w r)/((1 + q) r).
// Friction-limited: |F| <= mu N. Sticking when |F*| <= mu N, i.e.
// q |u| / (1 + q) <= mu (1 + e) |v_y|: then the no-slip result. Otherwise the
// ball slides, F = -mu N s with s = sign(u):
//   v_x' = v_x - mu (1 + e) |v_y| s,
//   w'   = w - mu (1 + e) |v_y| s / (q r).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "particles/world.h"
#include "physics_test_support.h"

namespace {

using namespace physics_test;
using particles::ContactMaterial;
using particles::kNoSlip;

constexpr std::uint64_t kSeed = 0x5eed'0007;
constexpr int kCases = 2000;

struct FloorHit {
  double m, r, q;
  double vx, vy, w;
  double e, mu;

  double slip() const { return vx + w * r; }
  bool sticks() const {
    return std::isinf(mu) || q * std::abs(slip()) / (1.0 + q) <= mu * (1.0 + e) * std::abs(vy);
  }
  // Distance from the sticking/sliding boundary, relative: cases within
  // rounding of it could legitimately go either way.
  bool nearBoundary() const {
    if (std::isinf(mu)) return false;
    const double a = q * std::abs(slip()) / (1.0 + q), b = mu * (1.0 + e) * std::abs(vy);
    return std::abs(a - b) <= 1e-9 * (a + b);
  }
  std::string describe() const {
    std::ostringstream s;
    s.precision(17);
    s << "m=" << m << " r=" << r << " q=" << q << " v=(" << vx << ", " << vy << ") w=" << w
      << " e=" << e << " mu=" << mu;
    return s.str();
  }
};

struct After {
  double vx, vy, w;
};

// The hand-derived answer.
After expected(const FloorHit& h) {
  const double vy = -h.e * h.vy;
  if (h.sticks()) {
    return {(h.vx - h.q * h.w * h.r) / (1.0 + h.q), vy,
            h.w - (h.vx + h.w * h.r) / ((1.0 + h.q) * h.r)};
  }
  const double s = h.slip() > 0.0 ? 1.0 : -1.0;
  const double f = h.mu * (1.0 + h.e) * std::abs(h.vy) * s;
  return {h.vx - f, vy, h.w - f / (h.q * h.r)};
}

After throughResolveImpact(const FloorHit& h) {
  Ball ball{Vec2(0.3, h.r), Vec2(h.vx, h.vy), h.w, h.m, h.r, h.q * h.m * h.r * h.r};
  particles::ContactBody a = contactBody(ball), wall = wallBody();
  particles::resolveImpact(a, wall, Vec2(0.0, -1.0), ContactMaterial{h.e, h.mu});
  return {a.velocity.x(), a.velocity.y(), a.angularVelocity};
}

After throughWorld(const FloorHit& h) {
  particles::SceneDef scene;
  scene.contact = ContactMaterial{h.e, h.mu};
  scene.dt = 1e-3;
  particles::WallDef floor;
  floor.a = Vec2(-10.0, 0.0);
  floor.b = Vec2(10.0, 0.0);
  scene.walls.push_back(floor);
  particles::BallDef ball;
  ball.position = Vec2(0.3, h.r);  // touching y = 0
  ball.velocity = Vec2(h.vx, h.vy);
  ball.angularVelocity = h.w;
  ball.radius = h.r;
  ball.mass = h.m;
  ball.inertia = h.q * h.m * h.r * h.r;
  scene.balls.push_back(ball);
  particles::World world(scene);
  world.step();
  EXPECT_EQ(world.stats().contacts, 1) << h.describe();
  const particles::BallState s = world.ball(0);
  // The step moved the ball with the post-impact velocity.
  const Vec2 moved = s.position - ball.position;
  EXPECT_NEAR(moved.x(), s.velocity.x() * scene.dt, kRoundingRel) << h.describe();
  EXPECT_NEAR(moved.y(), s.velocity.y() * scene.dt, kRoundingRel) << h.describe();
  return {s.velocity.x(), s.velocity.y(), s.angularVelocity};
}

// Checks the engine's answer against the hand-derived one; returns the
// largest difference relative to the speed scale.
double expectMatches(const FloorHit& h, const After& got) {
  const After want = expected(h);
  const double speed = std::hypot(h.vx, h.vy) + std::abs(h.w) * h.r;
  const double tol = kRoundingRel * speed;
  EXPECT_NEAR(got.vx, want.vx, tol) << h.describe();
  EXPECT_NEAR(got.vy, want.vy, tol) << h.describe();
  EXPECT_NEAR(got.w, want.w, tol / h.r) << h.describe();
  return std::max({std::abs(got.vx - want.vx), std::abs(got.vy - want.vy),
                   std::abs(got.w - want.w) * h.r}) /
         speed;
}

enum class Regime { NoSlip, Sticking, Sliding };

// Random floor hits of one regime (fixed seed); boundary cases are skipped.
std::vector<FloorHit> randomHits(Regime regime) {
  Random rand(kSeed + static_cast<std::uint64_t>(regime));
  std::vector<FloorHit> hits;
  while (static_cast<int>(hits.size()) < kCases) {
    FloorHit h;
    h.m = rand.logUniform(0.1, 10.0);
    h.r = rand.logUniform(0.05, 2.0);
    h.q = rand.uniform01() < 0.3 ? 0.5 : rand.uniform(0.1, 1.0);
    h.vx = rand.uniform(-3.0, 3.0);
    h.vy = -rand.uniform(0.1, 5.0);
    h.w = rand.uniform(-5.0, 5.0) / h.r;
    h.e = rand.uniform01();
    h.mu = regime == Regime::NoSlip ? kNoSlip : rand.logUniform(0.01, 3.0);
    if (h.nearBoundary()) continue;
    if (regime == Regime::Sticking && !h.sticks()) continue;
    if (regime == Regime::Sliding && h.sticks()) continue;
    hits.push_back(h);
  }
  return hits;
}

template <typename Engine>
void checkAll(Regime regime, Engine engine, const char* what) {
  Worst worst(what);
  std::uint64_t i = 0;
  for (const FloorHit& h : randomHits(regime)) worst.add(expectMatches(h, engine(h)), i++);
}

TEST(ClosedFormWall, NoSlipFloorImpactThroughResolveImpact) {
  checkAll(Regime::NoSlip, throughResolveImpact, "floor no-slip vs closed form (resolveImpact)");
}

TEST(ClosedFormWall, NoSlipFloorImpactThroughWorld) {
  checkAll(Regime::NoSlip, throughWorld, "floor no-slip vs closed form (World)");
}

// A consequence of the no-slip formulas: v_x' + w' r
// = (v_x - q w r)/(1 + q) + w r - (v_x + w r)/(1 + q) = 0: the ball leaves
// the floor rolling.
TEST(ClosedFormWall, NoSlipFloorImpactLeavesTheBallRolling) {
  Worst worst("floor no-slip: |v_x' + w' r| / speed");
  std::uint64_t i = 0;
  for (const FloorHit& h : randomHits(Regime::NoSlip)) {
    const After got = throughResolveImpact(h);
    const double speed = std::hypot(h.vx, h.vy) + std::abs(h.w) * h.r;
    worst.add(std::abs(got.vx + got.w * h.r) / speed, i++);
    EXPECT_NEAR(got.vx + got.w * h.r, 0.0, kRoundingRel * speed) << h.describe();
  }
}

TEST(ClosedFormWall, StickingFloorImpactThroughResolveImpact) {
  checkAll(Regime::Sticking, throughResolveImpact, "floor sticking vs closed form (resolveImpact)");
}

TEST(ClosedFormWall, StickingFloorImpactThroughWorld) {
  checkAll(Regime::Sticking, throughWorld, "floor sticking vs closed form (World)");
}

TEST(ClosedFormWall, SlidingFloorImpactThroughResolveImpact) {
  checkAll(Regime::Sliding, throughResolveImpact, "floor sliding vs closed form (resolveImpact)");
}

TEST(ClosedFormWall, SlidingFloorImpactThroughWorld) {
  checkAll(Regime::Sliding, throughWorld, "floor sliding vs closed form (World)");
}

// Two hand-computed numbers, so the formulas above are themselves pinned.
// Disk (q = 1/2), m = 2, r = 0.5, v = (3, -2), w = 0, e = 0.5:
//   no slip: v_x' = 3/1.5 = 2, w' = -3/(1.5 * 0.5) = -4, v_y' = 1;
//   mu = 0.2: |F*|/m = q u/(1+q) = 1 > mu (1+e)|v_y| = 0.6, so it slides:
//            v_x' = 3 - 0.6 = 2.4, w' = -0.6/(0.5 * 0.5) = -2.4.
TEST(ClosedFormWall, HandWorkedFloorImpacts) {
  const FloorHit noSlip{2.0, 0.5, 0.5, 3.0, -2.0, 0.0, 0.5, kNoSlip};
  const FloorHit sliding{2.0, 0.5, 0.5, 3.0, -2.0, 0.0, 0.5, 0.2};
  for (const After& got : {throughResolveImpact(noSlip), throughWorld(noSlip)}) {
    EXPECT_NEAR(got.vx, 2.0, 1e-14);
    EXPECT_NEAR(got.vy, 1.0, 1e-14);
    EXPECT_NEAR(got.w, -4.0, 1e-14);
  }
  for (const After& got : {throughResolveImpact(sliding), throughWorld(sliding)}) {
    EXPECT_NEAR(got.vx, 2.4, 1e-14);
    EXPECT_NEAR(got.vy, 1.0, 1e-14);
    EXPECT_NEAR(got.w, -2.4, 1e-14);
  }
}

}  // namespace
