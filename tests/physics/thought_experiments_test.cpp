// The handout's two thought experiments, through resolveImpact and through
// the World (two balls at exact contact, one step, no gravity).
//
// Setup (worked out by hand): two equal uniform disks, mass m, radius r,
// J = m r^2 / 2, a at (-r, 0) moving (+V, 0) and b at (+r, 0) moving (-V, 0).
// n = (1, 0), tau = (0, 1), contact point c = (0, 0).
//
// Surface velocities at c (v + w z x (c - x)):
//   a: c - x_a = (r, 0),  z x (r, 0) = (0, r)   -> (V, +w_a r)
//   b: c - x_b = (-r, 0), z x (-r, 0) = (0, -r) -> (-V, -w_b r)
//
// A tangential impulse lambda tau on b (and -lambda tau on a) gives
//   v_b,y += lambda/m, v_a,y -= lambda/m,
//   w_b += (c - x_b) x (lambda tau) / J = (-r)(lambda)/J = -2 lambda/(m r),
//   w_a += (c - x_a) x (-lambda tau) / J = (r)(-lambda)/J = -2 lambda/(m r):
// whatever lambda is, both spins change by the same amount and the sideways
// velocities are equal and opposite (the situation is symmetric under a half
// turn about c, which swaps the balls).
//
// (a) Same spin w_a = w_b = w: a's surface moves up (+w r), b's down (-w r).
//     No slip: w r - 3 lambda/m = 3 lambda/m - w r, so lambda = m w r / 3, and
//     v_a,y' = -w r/3, v_b,y' = +w r/3, w_a' = w_b' = w - 2w/3 = w/3.
//     Friction-limited and sliding (m w r/3 > mu lambda_n): lambda = mu lambda_n
//     with lambda_n = (1 + e) m V (equal masses, g_n = -2V, K_n = 2/m).
// (b) Opposite spins w_a = w, w_b = -w: both surfaces move up at w r (like
//     gears), no slip to cancel, lambda = 0: nothing tangential changes.
//
// Normal part for both: equal masses exchange V scaled by e: v_a,x' = -e V,
// v_b,x' = +e V.
#include <gtest/gtest.h>

#include <cmath>

#include "particles/world.h"
#include "physics_test_support.h"

namespace {

using namespace physics_test;
using particles::ContactMaterial;
using particles::kNoSlip;

constexpr double kM = 1.3, kR = 0.4;

struct HeadOn {
  double V, wa, wb, e, mu;
};

struct Outcome {
  Vec2 va, vb;
  double wa, wb;
};

Outcome throughResolveImpact(const HeadOn& h) {
  ImpactCase k;
  k.a = Ball{Vec2(-kR, 0.0), Vec2(h.V, 0.0), h.wa, kM, kR, 0.5 * kM * kR * kR};
  k.b = Ball{Vec2(kR, 0.0), Vec2(-h.V, 0.0), h.wb, kM, kR, 0.5 * kM * kR * kR};
  k.n = Vec2(1.0, 0.0);
  k.c = Vec2(0.0, 0.0);
  const ImpactResult r = collide(k, ContactMaterial{h.e, h.mu});
  return {r.a.v, r.b.v, r.a.w, r.b.w};
}

Outcome throughWorld(const HeadOn& h) {
  particles::SceneDef scene;
  scene.contact = ContactMaterial{h.e, h.mu};
  scene.dt = 1e-3;
  particles::BallDef a, b;
  a.position = Vec2(-kR, 0.0);
  b.position = Vec2(kR, 0.0);  // |x_b - x_a| = 2 r exactly: touching
  a.velocity = Vec2(h.V, 0.0);
  b.velocity = Vec2(-h.V, 0.0);
  a.angularVelocity = h.wa;
  b.angularVelocity = h.wb;
  a.radius = b.radius = kR;
  a.mass = b.mass = kM;  // inertia unset: uniform disk
  scene.balls = {a, b};
  particles::World world(scene);
  world.step();
  EXPECT_EQ(world.stats().contacts, 1);
  return {world.ball(0).velocity, world.ball(1).velocity, world.ball(0).angularVelocity,
          world.ball(1).angularVelocity};
}

double scaleOf(const HeadOn& h) {
  return std::abs(h.V) + (std::abs(h.wa) + std::abs(h.wb)) * kR;
}

void expectNear(double got, double want, double tol, const char* what, const HeadOn& h) {
  EXPECT_NEAR(got, want, tol) << what << " (V=" << h.V << " w_a=" << h.wa << " w_b=" << h.wb
                              << " e=" << h.e << " mu=" << h.mu << ")";
}

// The symmetric claims of (a): equal spin change, equal and opposite sideways
// velocities, normal exchange; and the no-slip closed form when it applies.
void checkSameSpin(const HeadOn& h, const Outcome& o) {
  const double tol = kRoundingRel * scaleOf(h);
  expectNear(o.wa - h.wa, o.wb - h.wb, tol / kR, "equal spin change", h);
  expectNear(o.va.y(), -o.vb.y(), tol, "equal and opposite sideways velocities", h);
  expectNear(o.va.x(), -h.e * h.V, tol, "normal: v_a,x' = -e V", h);
  expectNear(o.vb.x(), h.e * h.V, tol, "normal: v_b,x' = +e V", h);
  EXPECT_NE(o.vb.y(), 0.0) << "a same-spin impact with friction must push sideways";
  const double w = h.wa;
  const double noSlipLambda = kM * w * kR / 3.0;
  const double bound = h.mu * (1.0 + h.e) * kM * h.V;
  const double lambda =
      std::abs(noSlipLambda) <= bound ? noSlipLambda : std::copysign(bound, noSlipLambda);
  expectNear(o.vb.y(), lambda / kM, tol, "v_b,y' = lambda/m", h);
  expectNear(o.wb, w - 2.0 * lambda / (kM * kR), tol / kR, "w' = w - 2 lambda/(m r)", h);
  if (std::isinf(h.mu)) {
    expectNear(o.wa, w / 3.0, tol / kR, "no-slip: w' = w/3", h);
    expectNear(o.vb.y(), w * kR / 3.0, tol, "no-slip: v_b,y' = w r/3", h);
  }
}

const HeadOn kSameSpin[] = {
    {2.0, 5.0, 5.0, 1.0, kNoSlip},   {2.0, -5.0, -5.0, 1.0, kNoSlip},
    {0.5, 30.0, 30.0, 0.3, kNoSlip}, {3.0, 1.0, 1.0, 0.0, kNoSlip},
    {2.0, 5.0, 5.0, 1.0, 0.2},       // sticking: m w r/3 = 0.87 <= mu (1+e) m V = 1.04
    {2.0, 40.0, 40.0, 0.5, 0.1},     // sliding: 6.9 > 0.39
    {1.0, -25.0, -25.0, 0.8, 0.05},  // sliding: 4.3 > 0.12
};

TEST(ThoughtExperiments, SameSpinHeadOnThroughResolveImpact) {
  for (const HeadOn& h : kSameSpin) checkSameSpin(h, throughResolveImpact(h));
}

TEST(ThoughtExperiments, SameSpinHeadOnThroughWorld) {
  for (const HeadOn& h : kSameSpin) checkSameSpin(h, throughWorld(h));
}

void checkOppositeSpin(const HeadOn& h, const Outcome& o) {
  const double tol = kRoundingRel * scaleOf(h);
  expectNear(o.wa, h.wa, tol / kR, "spin of a unchanged", h);
  expectNear(o.wb, h.wb, tol / kR, "spin of b unchanged", h);
  expectNear(o.va.y(), 0.0, tol, "no sideways velocity for a", h);
  expectNear(o.vb.y(), 0.0, tol, "no sideways velocity for b", h);
  expectNear(o.va.x(), -h.e * h.V, tol, "normal: v_a,x' = -e V", h);
  expectNear(o.vb.x(), h.e * h.V, tol, "normal: v_b,x' = +e V", h);
}

const HeadOn kOppositeSpin[] = {
    {2.0, 5.0, -5.0, 1.0, kNoSlip},   {2.0, -5.0, 5.0, 1.0, kNoSlip},
    {0.5, 30.0, -30.0, 0.3, kNoSlip}, {2.0, 40.0, -40.0, 0.5, 0.1},
    {1.0, -25.0, 25.0, 0.0, 0.7},
};

TEST(ThoughtExperiments, OppositeSpinsExchangeNoTangentialImpulseThroughResolveImpact) {
  for (const HeadOn& h : kOppositeSpin) checkOppositeSpin(h, throughResolveImpact(h));
}

TEST(ThoughtExperiments, OppositeSpinsExchangeNoTangentialImpulseThroughWorld) {
  for (const HeadOn& h : kOppositeSpin) checkOppositeSpin(h, throughWorld(h));
}

}  // namespace
