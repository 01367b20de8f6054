// The impact law of a single ball-ball contact, regime by regime, on random
// approaching impacts (physics_test_support.h):
//
//  * normal:   g_n' = -e g_n (restitution), for every friction mode;
//  * no-slip:  g_t' = 0, the surfaces leave with equal tangential velocities;
//  * Coulomb:  |lambda_t| <= mu lambda_n, lambda_t has the sign of the no-slip
//              impulse lambda_t*; sticking (|lambda_t*| <= mu lambda_n) gives
//              exactly the no-slip impact, sliding takes the full bound and
//              only shrinks the slip, never reverses it;
//  * smooth:   no tangential impulse at all.
//
// g_n, g_t are measured here from the geometry: the velocity of each ball's
// material point at the contact c is v + w z x (c - x).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "physics_test_support.h"

namespace {

using namespace physics_test;
using particles::ContactMaterial;

constexpr std::uint64_t kSeed = 0x5eed'0002;

// Speeds before and after: the scale of any rounding in a contact velocity.
double speedScale(const ImpactCase& k, const ImpactResult& r) {
  return physics_test::speedScale(k.a, k.b) + physics_test::speedScale(r.a, r.b);
}

TEST(ImpulseRegimes, NormalRelativeVelocityIsMinusETimesBefore) {
  ImpactGenerator gen(kSeed);
  Worst worst("|g_n' + e g_n| / speed scale");
  for (Friction mode : kAllModes) {
    for (int i = 0; i < kCasesPerMode; ++i) {
      const ImpactCase k = gen.next(mode);
      const ImpactResult r = collide(k);
      const double gn = contactSlip(k.a, k.b, k.n, k.c).normal;
      const double gnAfter = contactSlip(r.a, r.b, k.n, k.c).normal;
      const double residual = std::abs(gnAfter + k.material.restitution * gn) / speedScale(k, r);
      worst.add(residual, k.index);
      ASSERT_LE(residual, kRoundingRel) << "g_n " << gn << " -> " << gnAfter << "\n"
                                        << k.describe();
      ASSERT_GT(r.impulse.normal, 0.0) << "an approaching contact must be pushed apart\n"
                                       << k.describe();
    }
  }
}

TEST(ImpulseRegimes, NoSlipLeavesEqualTangentialSurfaceVelocities) {
  ImpactGenerator gen(kSeed);
  Worst worst("no-slip residual |g_t'| / speed scale");
  for (int i = 0; i < kCasesPerMode; ++i) {
    const ImpactCase k = gen.next(Friction::NoSlip);
    const ImpactResult r = collide(k);
    const double gtAfter = contactSlip(r.a, r.b, k.n, k.c).tangent;
    const double residual = std::abs(gtAfter) / speedScale(k, r);
    worst.add(residual, k.index);
    ASSERT_LE(residual, kRoundingRel) << "g_t' = " << gtAfter << "\n" << k.describe();
  }
}

// The impulse the engine reports is the one it applied: b's momentum changes
// by +P, a's by -P, and each spin by the moment of that impulse about the
// centre, (c - x) x (impulse on the ball).
TEST(ImpulseRegimes, ReportedImpulseIsTheAppliedImpulse) {
  ImpactGenerator gen(kSeed);
  Worst worst("|applied - reported impulse| / scale");
  for (Friction mode : kAllModes) {
    for (int i = 0; i < kCasesPerMode; ++i) {
      const ImpactCase k = gen.next(mode);
      const ImpactResult r = collide(k);
      const Vec2 p = r.impulse.normal * k.n + r.impulse.tangent * zCross(k.n);
      auto check = [&](const Ball& before, const Ball& after, const Vec2& received,
                       const char* which) {
        const double scale = before.m * (before.v.norm() + after.v.norm()) + p.norm();
        const double linear = (before.m * (after.v - before.v) - received).norm() / scale;
        const double angularScale =
            before.J * (std::abs(before.w) + std::abs(after.w)) + before.r * p.norm();
        const double angular =
            std::abs(before.J * (after.w - before.w) - crossZ(k.c - before.x, received)) /
            angularScale;
        worst.add(std::max(linear, angular), k.index);
        EXPECT_LE(linear, kRoundingRel) << "ball " << which << "\n" << k.describe();
        EXPECT_LE(angular, kRoundingRel) << "ball " << which << "\n" << k.describe();
      };
      check(k.a, r.a, -p, "a");
      check(k.b, r.b, p, "b");
      if (::testing::Test::HasFailure()) return;
    }
  }
}

// Friction-limited impacts, each compared with the same impact under no-slip
// (whose g_t' = 0 is checked above): that run's tangential impulse is the
// unclamped lambda_t*.
struct LimitedVsNoSlip {
  ImpactCase k;
  ImpactResult limited, noSlip;
  double bound = 0.0;  // mu lambda_n
};
template <typename Check>
void forEachLimited(std::uint64_t seed, Check check) {
  ImpactGenerator gen(seed);
  for (int i = 0; i < kCasesPerMode; ++i) {
    LimitedVsNoSlip c;
    c.k = gen.next(Friction::Limited);
    c.limited = collide(c.k);
    c.noSlip = collide(c.k, ContactMaterial{c.k.material.restitution, particles::kNoSlip});
    c.bound = c.k.material.friction * c.limited.impulse.normal;
    check(c);
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(ImpulseRegimes, FrictionImpulseWithinCoulombBound) {
  Worst worst("(|lambda_t| - mu lambda_n) / (mu lambda_n), positive part");
  forEachLimited(kSeed, [&](const LimitedVsNoSlip& c) {
    const double lt = c.limited.impulse.tangent;
    worst.add((std::abs(lt) - c.bound) / c.bound, c.k.index);
    EXPECT_LE(std::abs(lt), c.bound * (1.0 + kRoundingRel))
        << "lambda_t " << lt << ", mu lambda_n " << c.bound << "\n"
        << c.k.describe();
  });
}

TEST(ImpulseRegimes, FrictionImpulseHasTheSignOfTheNoSlipImpulse) {
  Worst worst("|reported unclamped - no-slip lambda_t| / |no-slip lambda_t|");
  forEachLimited(kSeed, [&](const LimitedVsNoSlip& c) {
    const double star = c.noSlip.impulse.tangent;
    const double lt = c.limited.impulse.tangent;
    EXPECT_TRUE(std::signbit(lt) == std::signbit(star) || lt == 0.0)
        << "lambda_t " << lt << ", no-slip lambda_t* " << star << "\n"
        << c.k.describe();
    // The reported "unclamped" value is the no-slip impulse.
    const double rel = std::abs(c.limited.impulse.unclamped - star) / std::abs(star);
    worst.add(rel, c.k.index);
    EXPECT_LE(rel, kRoundingRel) << c.k.describe();
  });
}

// Both regimes must be well represented, or the two tests below prove little.
TEST(ImpulseRegimes, RandomFrictionCasesCoverStickingAndSliding) {
  int sticking = 0, sliding = 0;
  forEachLimited(kSeed, [&](const LimitedVsNoSlip& c) {
    (std::abs(c.noSlip.impulse.tangent) <= c.bound ? sticking : sliding)++;
  });
  std::printf("[ measured ] friction-limited cases: %d sticking, %d sliding\n", sticking, sliding);
  EXPECT_GT(sticking, kCasesPerMode / 10);
  EXPECT_GT(sliding, kCasesPerMode / 10);
}

TEST(ImpulseRegimes, StickingFrictionGivesTheNoSlipImpact) {
  Worst worst("sticking vs no-slip: velocity difference / speed scale");
  forEachLimited(kSeed, [&](const LimitedVsNoSlip& c) {
    const double star = std::abs(c.noSlip.impulse.tangent);
    // Cases within rounding of the boundary could go either way.
    if (star > c.bound * (1.0 - 1e-9)) return;
    const double scale = speedScale(c.k, c.noSlip);
    const double diff =
        std::max({(c.limited.a.v - c.noSlip.a.v).norm(), (c.limited.b.v - c.noSlip.b.v).norm(),
                  std::abs(c.limited.a.w - c.noSlip.a.w) * c.k.a.r,
                  std::abs(c.limited.b.w - c.noSlip.b.w) * c.k.b.r}) /
        scale;
    worst.add(diff, c.k.index);
    EXPECT_LE(diff, kRoundingRel) << c.k.describe();
    EXPECT_FALSE(c.limited.impulse.clamped) << c.k.describe();
  });
}

// Sliding: friction acts at its Coulomb limit for the whole impact, so
// |lambda_t| = mu lambda_n, and since |lambda_t| < |lambda_t*| the slip
// g_t' = g_t + lambda_t K_t lies strictly between g_t and 0: it shrinks and
// keeps its sign.
TEST(ImpulseRegimes, SlidingFrictionTakesTheFullBoundAndNeverReversesSlip) {
  Worst worst("sliding: | |lambda_t| - mu lambda_n | / (mu lambda_n)");
  forEachLimited(kSeed, [&](const LimitedVsNoSlip& c) {
    const double star = std::abs(c.noSlip.impulse.tangent);
    if (star < c.bound * (1.0 + 1e-9)) return;
    const double lt = c.limited.impulse.tangent;
    const double rel = std::abs(std::abs(lt) - c.bound) / c.bound;
    worst.add(rel, c.k.index);
    EXPECT_LE(rel, kRoundingRel) << c.k.describe();
    EXPECT_TRUE(c.limited.impulse.clamped) << c.k.describe();
    const double gt = contactSlip(c.k.a, c.k.b, c.k.n, c.k.c).tangent;
    const double gtAfter = contactSlip(c.limited.a, c.limited.b, c.k.n, c.k.c).tangent;
    EXPECT_GT(gt * gtAfter, 0.0) << "slip reversed or stopped: " << gt << " -> " << gtAfter << "\n"
                                 << c.k.describe();
    EXPECT_LT(std::abs(gtAfter), std::abs(gt)) << c.k.describe();
  });
}

// Smooth (mu = 0): only the normal impulse acts. It passes through both
// centres, so spins are untouched, and it is along n, so each ball's velocity
// component along tau is untouched.
TEST(ImpulseRegimes, SmoothImpactExchangesNoTangentialImpulse) {
  ImpactGenerator gen(kSeed);
  Worst worst("smooth: change of tangential velocity / speed scale");
  for (int i = 0; i < kCasesPerMode; ++i) {
    const ImpactCase k = gen.next(Friction::Smooth);
    const ImpactResult r = collide(k);
    const Vec2 tau = zCross(k.n);
    EXPECT_EQ(r.impulse.tangent, 0.0) << k.describe();
    EXPECT_EQ(r.a.w, k.a.w) << k.describe();
    EXPECT_EQ(r.b.w, k.b.w) << k.describe();
    const double change =
        std::max(std::abs((r.a.v - k.a.v).dot(tau)), std::abs((r.b.v - k.b.v).dot(tau))) /
        speedScale(k, r);
    worst.add(change, k.index);
    EXPECT_LE(change, kRoundingRel) << k.describe();
    if (::testing::Test::HasFailure()) return;
  }
}

// Frame independence. Calling the balls (b, a) with the normal -n is the same
// physical impact, and so is the whole scene turned by an angle: the
// results must be the same balls' velocities (turned with the scene).
TEST(ImpulseRegimes, SwappingTheBallsGivesTheSameImpact) {
  ImpactGenerator gen(kSeed + 7);
  Worst worst("swap a <-> b: velocity difference / speed scale");
  for (Friction mode : kAllModes) {
    for (int i = 0; i < kCasesPerMode; ++i) {
      const ImpactCase k = gen.next(mode);
      ImpactCase swapped = k;
      swapped.a = k.b;
      swapped.b = k.a;
      swapped.n = -k.n;
      const ImpactResult r = collide(k);
      const ImpactResult s = collide(swapped);
      const double diff =
          std::max({(r.a.v - s.b.v).norm(), (r.b.v - s.a.v).norm(), std::abs(r.a.w - s.b.w) * k.a.r,
                    std::abs(r.b.w - s.a.w) * k.b.r}) /
          speedScale(k, r);
      worst.add(diff, k.index);
      ASSERT_LE(diff, kRoundingRel) << k.describe();
    }
  }
}

TEST(ImpulseRegimes, RotatingTheSceneRotatesTheImpact) {
  ImpactGenerator gen(kSeed + 8);
  Random rand(kSeed + 9);
  Worst worst("rotated scene: velocity difference / speed scale");
  for (Friction mode : kAllModes) {
    for (int i = 0; i < kCasesPerMode; ++i) {
      const ImpactCase k = gen.next(mode);
      const double angle = rand.uniform(-3.0, 3.0);
      const Eigen::Matrix2d rot = Eigen::Rotation2Dd(angle).toRotationMatrix();
      ImpactCase turned = k;
      for (Ball* b : {&turned.a, &turned.b}) {
        b->x = rot * b->x;
        b->v = rot * b->v;
      }
      turned.c = rot * k.c;
      turned.n = rot * k.n;
      const ImpactResult r = collide(k);
      const ImpactResult s = collide(turned);
      const double diff =
          std::max({(rot * r.a.v - s.a.v).norm(), (rot * r.b.v - s.b.v).norm(),
                    std::abs(r.a.w - s.a.w) * k.a.r, std::abs(r.b.w - s.b.w) * k.b.r}) /
          speedScale(k, r);
      worst.add(diff, k.index);
      ASSERT_LE(diff, kRoundingRel) << "angle " << angle << "\n" << k.describe();
    }
  }
}

}  // namespace
