// Invariants of a single ball-ball impact (resolveImpact), over thousands of
// random approaching impacts per friction mode (no-slip, friction-limited,
// smooth): see physics_test_support.h for the ranges.
//
// Why they must hold:
//  * Linear momentum: b receives +P and a receives -P (Newton's third law),
//    so m_a v_a + m_b v_b cannot change.
//  * Angular momentum of each ball about the contact point c,
//    L = J w + m (x - c) x v: the only impulse on a ball acts at c, and an
//    impulse through c has no moment about c. So each ball keeps its own L.
//  * Energy: for balls the contact point lies on the line of centres, so a
//    normal impulse changes only g_n and a tangential one only g_t. The work
//    of an impulse lambda applied while a relative velocity goes from g to g'
//    is lambda (g + g')/2. Normal part: g_n' = -e g_n with lambda_n opposite
//    to g_n, so lambda_n (1 - e) g_n / 2 <= 0. Tangential part: lambda_t
//    opposes g_t and g_t' lies between 0 and g_t, so it is <= 0. Hence
//    E' <= E, and E' = E exactly when e = 1 and lambda_t = 0 (smooth).
#include <gtest/gtest.h>

#include <cmath>

#include "physics_test_support.h"

namespace {

using namespace physics_test;

constexpr std::uint64_t kSeed = 0x5eed'0001;

TEST(ImpulseConservation, LinearMomentumConservedInEveryMode) {
  ImpactGenerator gen(kSeed);
  Worst worst("linear momentum residual / momentum scale");
  for (Friction mode : kAllModes) {
    for (int i = 0; i < kCasesPerMode; ++i) {
      const ImpactCase k = gen.next(mode);
      const ImpactResult r = collide(k);
      const Vec2 before = momentum(k.a) + momentum(k.b);
      const Vec2 after = momentum(r.a) + momentum(r.b);
      // Scale: every momentum term that enters the sums.
      const double scale =
          k.a.m * (k.a.v.norm() + r.a.v.norm()) + k.b.m * (k.b.v.norm() + r.b.v.norm());
      const double residual = (after - before).norm() / scale;
      worst.add(residual, k.index);
      ASSERT_LE(residual, kRoundingRel) << k.describe();
    }
  }
}

TEST(ImpulseConservation, AngularMomentumAboutContactConservedForEachBall) {
  ImpactGenerator gen(kSeed);
  Worst worst("angular momentum (about c) residual / scale, per ball");
  for (Friction mode : kAllModes) {
    for (int i = 0; i < kCasesPerMode; ++i) {
      const ImpactCase k = gen.next(mode);
      const ImpactResult r = collide(k);
      auto check = [&](const Ball& before, const Ball& after, const char* which) {
        const double scale = before.J * (std::abs(before.w) + std::abs(after.w)) +
                             before.m * before.r * (before.v.norm() + after.v.norm());
        const double residual =
            std::abs(angularMomentumAbout(after, k.c) - angularMomentumAbout(before, k.c)) / scale;
        worst.add(residual, k.index);
        EXPECT_LE(residual, kRoundingRel) << "ball " << which << "\n" << k.describe();
      };
      check(k.a, r.a, "a");
      check(k.b, r.b, "b");
      if (::testing::Test::HasFailure()) return;
    }
  }
}

TEST(ImpulseEnergy, NeverIncreases) {
  ImpactGenerator gen(kSeed);
  Worst worst("energy gain / energy before (positive part)");
  int dissipating = 0;
  for (Friction mode : kAllModes) {
    for (int i = 0; i < kCasesPerMode; ++i) {
      const ImpactCase k = gen.next(mode);
      const ImpactResult r = collide(k);
      const double before = kineticEnergy(k.a) + kineticEnergy(k.b);
      const double after = kineticEnergy(r.a) + kineticEnergy(r.b);
      worst.add((after - before) / before, k.index);
      dissipating += after < before * (1.0 - 1e-6);
      ASSERT_LE(after - before, kRoundingRel * before)
          << "E before " << before << ", after " << after << "\n"
          << k.describe();
    }
  }
  // Not vacuous: most random impacts lose a visible amount of energy.
  EXPECT_GT(dissipating, kCasesPerMode);
}

TEST(ImpulseEnergy, SmoothElasticConservesEnergy) {
  ImpactGenerator gen(kSeed + 1);
  Worst worst("|energy change| / energy, smooth e = 1");
  for (int i = 0; i < kCasesPerMode; ++i) {
    ImpactCase k = gen.next(Friction::Smooth);
    k.material.restitution = 1.0;
    const ImpactResult r = collide(k);
    const double before = kineticEnergy(k.a) + kineticEnergy(k.b);
    const double after = kineticEnergy(r.a) + kineticEnergy(r.b);
    worst.add(std::abs(after - before) / before, k.index);
    ASSERT_LE(std::abs(after - before), kRoundingRel * before)
        << "E before " << before << ", after " << after << "\n"
        << k.describe();
  }
}

// The energy lost by a smooth impact, worked out by hand: lambda_n must change
// g_n into -e g_n, and a unit lambda_n changes g_n by K_n = 1/m_a + 1/m_b, so
// lambda_n = -(1 + e) g_n / K_n. Its work is lambda_n (g_n + g_n')/2
// = -(1 + e)(1 - e) g_n^2 / (2 K_n) = -(1 - e^2) mu_red g_n^2 / 2 with the
// reduced mass mu_red = 1/K_n; there is no tangential work. This checks the
// amount, not just the sign.
TEST(ImpulseEnergy, SmoothImpactLosesTheNormalRestitutionEnergy) {
  ImpactGenerator gen(kSeed + 2);
  Worst worst("smooth impact: |dE - closed form| / E");
  for (int i = 0; i < kCasesPerMode; ++i) {
    const ImpactCase k = gen.next(Friction::Smooth);
    const ImpactResult r = collide(k);
    const double e = k.material.restitution;
    const double gn = contactSlip(k.a, k.b, k.n, k.c).normal;
    const double reducedMass = 1.0 / (1.0 / k.a.m + 1.0 / k.b.m);
    const double expected = -0.5 * reducedMass * (1.0 - e * e) * gn * gn;
    const double before = kineticEnergy(k.a) + kineticEnergy(k.b);
    const double after = kineticEnergy(r.a) + kineticEnergy(r.b);
    const double residual = std::abs((after - before) - expected) / before;
    worst.add(residual, k.index);
    ASSERT_LE(residual, kRoundingRel)
        << "dE " << after - before << ", expected " << expected << "\n"
        << k.describe();
  }
}

}  // namespace
