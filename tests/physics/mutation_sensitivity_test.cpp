// The invariant checks of this suite are sharp enough to notice each wrong
// sign the handout could have led to: every deliberately wrong solver of
// particles::Mutation (the real solver with one sign changed) breaks at least
// one physical invariant on random impacts, while the real solver keeps them
// all to rounding. An invariant that no mutant could break would prove
// nothing about the signs.
//
// Invariants checked on each impact (ball-ball, and ball-wall with the wall as
// body b), all measured from the geometry as in the other tests:
//   momentum       m_a v_a + m_b v_b unchanged (ball-ball)
//   angular        each ball's J w + m (x - c) x v unchanged
//   energy         kinetic energy does not grow
//   restitution    g_n' = -e g_n
//   no-slip        g_t' = 0 (mu = kNoSlip)
//   friction       lambda_t opposes the slip (lambda_t g_t <= 0), the slip
//                  is not reversed (g_t' g_t >= 0), |lambda_t| <= mu lambda_n
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "physics_test_support.h"

namespace {

using namespace physics_test;
using particles::Mutation;

enum Invariant { kMomentum, kAngular, kEnergy, kRestitution, kNoSlipResidual, kFriction, kCount };
const char* kInvariantNames[] = {"momentum",    "angular", "energy",
                                 "restitution", "no-slip", "friction"};

using Violations = std::array<double, kCount>;  // worst relative violation of each

void worsen(Violations& v, Invariant i, double value) {
  v[i] = std::max(v[i], value);
}

// One impact under mutation m; `wall` makes body b a wall (ball b of the case
// is then ignored).
void check(const ImpactCase& k, bool wall, Mutation m, Violations& v) {
  particles::ContactBody a = contactBody(k.a);
  particles::ContactBody b = wall ? wallBody() : contactBody(k.b);
  Ball bBefore = k.b;
  if (wall) bBefore = Ball{k.b.x, Vec2(0.0, 0.0), 0.0, 1.0, k.b.r, 1.0};
  const particles::ContactImpulse j = particles::resolveImpact(a, b, k.n, k.material, m);
  Ball aAfter = k.a, bAfter = bBefore;
  aAfter.v = a.velocity;
  aAfter.w = a.angularVelocity;
  if (!wall) {
    bAfter.v = b.velocity;
    bAfter.w = b.angularVelocity;
  }
  const double speed = speedScale(k.a, bBefore) + speedScale(aAfter, bAfter);
  const Slip before = contactSlip(k.a, bBefore, k.n, k.c);
  const Slip after = contactSlip(aAfter, bAfter, k.n, k.c);

  if (!wall) {
    const double scale =
        k.a.m * (k.a.v.norm() + aAfter.v.norm()) + k.b.m * (k.b.v.norm() + bAfter.v.norm());
    worsen(v, kMomentum,
           (momentum(aAfter) + momentum(bAfter) - momentum(k.a) - momentum(k.b)).norm() / scale);
  }
  auto angular = [&](const Ball& x, const Ball& y) {
    const double scale =
        x.J * (std::abs(x.w) + std::abs(y.w)) + x.m * x.r * (x.v.norm() + y.v.norm());
    worsen(v, kAngular,
           std::abs(angularMomentumAbout(y, k.c) - angularMomentumAbout(x, k.c)) / scale);
  };
  angular(k.a, aAfter);
  if (!wall) angular(k.b, bAfter);
  const double E0 = kineticEnergy(k.a) + (wall ? 0.0 : kineticEnergy(k.b));
  const double E1 = kineticEnergy(aAfter) + (wall ? 0.0 : kineticEnergy(bAfter));
  worsen(v, kEnergy, (E1 - E0) / E0);
  worsen(v, kRestitution, std::abs(after.normal + k.material.restitution * before.normal) / speed);
  if (std::isinf(k.material.friction)) worsen(v, kNoSlipResidual, std::abs(after.tangent) / speed);
  if (k.material.friction > 0.0) {
    const double lt = j.tangent;
    // lambda_t g_t <= 0 and g_t' g_t >= 0, relative to the scales involved.
    worsen(v, kFriction, lt * before.tangent / (std::abs(lt) * speed + 1e-300));
    worsen(v, kFriction, -after.tangent * before.tangent / (speed * speed));
    if (!std::isinf(k.material.friction))
      worsen(v, kFriction, (std::abs(lt) - k.material.friction * j.normal) / std::abs(j.normal));
  }
}

Violations violationsOf(Mutation m) {
  Violations v{};
  ImpactGenerator gen(0x5eed'0041);
  for (Friction mode : kAllModes) {
    for (int i = 0; i < 500; ++i) {
      const ImpactCase k = gen.next(mode);
      check(k, false, m, v);
      // Against a wall: ball a must approach it (v_a . n > 0).
      ImpactCase w = k;
      if (w.a.v.dot(w.n) < 0.0) w.a.v -= 2.0 * w.a.v.dot(w.n) * w.n;
      if (w.a.v.dot(w.n) > 0.01) check(w, true, m, v);
    }
  }
  return v;
}

std::string describe(const Violations& v) {
  std::string s;
  char buf[64];
  for (int i = 0; i < kCount; ++i) {
    std::snprintf(buf, sizeof buf, " %s %.1e", kInvariantNames[i], v[i]);
    s += buf;
  }
  return s;
}

TEST(MutationSensitivity, RealSolverKeepsEveryInvariant) {
  const Violations v = violationsOf(Mutation::None);
  for (int i = 0; i < kCount; ++i) EXPECT_LE(v[i], kRoundingRel) << kInvariantNames[i];
}

// A violation of 1e-6 of the scale is 10^6 times the rounding allowance: a
// mutant "caught" here is caught by physics, not by noise.
TEST(MutationSensitivity, EveryWrongSignBreaksAnInvariant) {
  for (Mutation m : particles::kAllMutations) {
    const Violations v = violationsOf(m);
    const double worst = *std::max_element(v.begin(), v.end());
    std::printf("[ measured ] mutant '%s':%s\n", std::string(particles::mutationName(m)).c_str(),
                describe(v).c_str());
    EXPECT_GT(worst, 1e-6) << "mutant '" << particles::mutationName(m)
                           << "' passes every invariant";
  }
}

}  // namespace
