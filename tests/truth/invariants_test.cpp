// Invariants of the closed-form truth on many random impacts (fixed seed, portable generator):
// linear momentum, each disc's angular momentum about the contact point, restitution, the
// tangential law of each regime, and the energy change predicted by the effective masses.
// Then the wall as the limit of a disc of mass 1e15.
//
// The checks are written in the test's own terms: positions x_a = 0, x_b = (r_a + r_b) n,
// c = r_a n and 2D cross products, not the library's (tau . v) shortcuts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "particles/truth/closed_form.h"
#include "truth_test_util.h"

namespace {

using particles::truth::Body;
using particles::truth::Impact;
using particles::truth::Regime;
using particles::truth::solveImpact;
using truth_test::cross;
using truth_test::dot;
using truth_test::kTol;
using truth_test::Real;
using truth_test::Vec;
using truth_test::vel;

constexpr Real kInf = std::numeric_limits<Real>::infinity();

/// SplitMix64: tiny, portable and reproducible on every standard library (unlike the
/// std:: distributions, whose output is implementation-defined).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  Real uniform(Real lo, Real hi) {
    return lo + (hi - lo) * static_cast<Real>(next() >> 11) * 0x1.0p-53L;
  }
  Real logUniform(Real lo, Real hi) { return lo * std::pow(hi / lo, uniform(0, 1)); }

 private:
  std::uint64_t state_;
};

Body randomDisc(Rng& rng) {
  Body b;
  b.mass = rng.logUniform(0.1L, 10);
  b.radius = rng.logUniform(0.1L, 2);
  // J = k m r^2 with k from 0.1 (mass concentrated at the centre) to 1 (a ring).
  b.inertia = rng.uniform(0.1L, 1) * b.mass * b.radius * b.radius;
  b.vx = rng.uniform(-5, 5);
  b.vy = rng.uniform(-5, 5);
  b.w = rng.uniform(-5, 5) / b.radius;
  return b;
}

struct Case {
  Body a, b;
  Real nx, ny, e, mu;
};

Case randomCase(Rng& rng, bool withWall) {
  Case c;
  c.a = randomDisc(rng);
  c.b = randomDisc(rng);
  c.b.wall = withWall;
  const Real angle = rng.uniform(-3.14159265358979323846L, 3.14159265358979323846L);
  c.nx = std::cos(angle);
  c.ny = std::sin(angle);
  const Real pickE = rng.uniform(0, 1);
  c.e = pickE < 0.1L ? 0 : pickE < 0.2L ? 1 : rng.uniform(0, 1);
  const Real pickMu = rng.uniform(0, 1);
  c.mu = pickMu < 0.1L ? 0 : pickMu < 0.2L ? kInf : rng.uniform(0, 1.5L);
  return c;
}

Real energy(const Body& b) {
  return b.wall ? 0 : 0.5L * b.mass * (b.vx * b.vx + b.vy * b.vy) + 0.5L * b.inertia * b.w * b.w;
}

/// Relative velocities at the contact, computed from the velocity of each material point at c:
/// v + w z x (c - x). (z x d = (-d_y, d_x).)
struct Gaps {
  Real gn, gt;
};
Gaps gaps(const Body& a, const Body& b, Vec n) {
  const Vec tau{-n.y, n.x};
  const Vec da{a.radius * n.x, a.radius * n.y};  // c - x_a
  const Vec pa{a.vx - a.w * da.y, a.vy + a.w * da.x};
  Vec pb{0, 0};
  if (!b.wall) {
    const Vec db{-b.radius * n.x, -b.radius * n.y};  // c - x_b
    pb = {b.vx - b.w * db.y, b.vy + b.w * db.x};
  }
  const Vec rel{pb.x - pa.x, pb.y - pa.y};
  return {dot(rel, n), dot(rel, tau)};
}

/// Angular momentum about c: J w + m (x - c) x v.
Real angularMomentumAboutC(const Body& body, Vec xMinusC) {
  return body.inertia * body.w + body.mass * cross(xMinusC, vel(body));
}

struct Counts {
  int separating = 0, smooth = 0, sticking = 0, sliding = 0;
};

void checkCase(const Case& k, Counts& counts) {
  const Impact out = solveImpact(k.a, k.b, k.nx, k.ny, k.e, k.mu);
  const Vec n{k.nx, k.ny}, tau{-k.ny, k.nx};
  const Body &a = k.a, &b = k.b, &a2 = out.a, &b2 = out.b;
  const bool wall = b.wall;

  // Natural scales: speeds at the contact, momenta, energy.
  const Real speed = std::hypot(a.vx, a.vy) + a.radius * std::fabs(a.w) + std::hypot(a2.vx, a2.vy) +
                     a2.radius * std::fabs(a2.w) +
                     (wall ? 0
                           : std::hypot(b.vx, b.vy) + b.radius * std::fabs(b.w) +
                                 std::hypot(b2.vx, b2.vy) + b2.radius * std::fabs(b2.w));
  const Gaps g = gaps(a, b, n), g2 = gaps(a2, b2, n);

  if (!(g.gn < 0)) {
    ++counts.separating;
    EXPECT_EQ(out.regime, Regime::Separating);
    EXPECT_EQ(out.normalImpulse, 0);
    EXPECT_EQ(a2.vx, a.vx);
    EXPECT_EQ(a2.w, a.w);
    EXPECT_EQ(b2.vy, b.vy);
    return;
  }
  EXPECT_GT(out.normalImpulse, 0) << "J_n >= 0 (and > 0 when approaching)";

  // The reported impulse is the momentum change: on b +(J_n n + J_t tau), on a the opposite.
  const Real jx = out.normalImpulse * n.x + out.tangentImpulse * tau.x;
  const Real jy = out.normalImpulse * n.y + out.tangentImpulse * tau.y;
  const Real pScale = a.mass * speed + (wall ? 0 : b.mass * speed);
  EXPECT_CLOSE("impulse = -m_a dv_a", a.mass * (a2.vx - a.vx), -jx, pScale);
  EXPECT_CLOSE("impulse = -m_a dv_a", a.mass * (a2.vy - a.vy), -jy, pScale);
  if (!wall) {
    EXPECT_CLOSE("impulse = m_b dv_b", b.mass * (b2.vx - b.vx), jx, pScale);
    EXPECT_CLOSE("impulse = m_b dv_b", b.mass * (b2.vy - b.vy), jy, pScale);
    // Total linear momentum.
    EXPECT_CLOSE("linear momentum", a.mass * a2.vx + b.mass * b2.vx, a.mass * a.vx + b.mass * b.vx,
                 pScale);
    EXPECT_CLOSE("linear momentum", a.mass * a2.vy + b.mass * b2.vy, a.mass * a.vy + b.mass * b.vy,
                 pScale);
  }

  // Angular momentum of each disc about the contact point (the contact force acts at c).
  const Vec xaMinusC{-a.radius * n.x, -a.radius * n.y};
  EXPECT_CLOSE("angular momentum about c", angularMomentumAboutC(a2, xaMinusC),
               angularMomentumAboutC(a, xaMinusC),
               a.inertia * speed / std::max(a.radius, 0.1L) + a.mass * a.radius * speed);
  if (!wall) {
    const Vec xbMinusC{b.radius * n.x, b.radius * n.y};
    EXPECT_CLOSE("angular momentum about c", angularMomentumAboutC(b2, xbMinusC),
                 angularMomentumAboutC(b, xbMinusC),
                 b.inertia * speed / std::max(b.radius, 0.1L) + b.mass * b.radius * speed);
  }

  // Restitution.
  EXPECT_CLOSE("restitution g_n' = -e g_n", g2.gn, -k.e * g.gn, speed);

  // Effective masses, from the test's own derivation: a unit impulse along n changes g_n by
  // 1/m_a + 1/m_b; along tau it changes g_t by 1/m_a + 1/m_b + r_a^2/J_a + r_b^2/J_b.
  const Real invMn = 1 / a.mass + (wall ? 0 : 1 / b.mass);
  const Real invMt =
      invMn + a.radius * a.radius / a.inertia + (wall ? 0 : b.radius * b.radius / b.inertia);
  EXPECT_CLOSE("J_n = M_n (1 + e)|g_n|", out.normalImpulse, (1 + k.e) * -g.gn / invMn,
               speed / invMn);

  // Energy: dE = -1/2 M_n (g_n^2 - g_n'^2) - 1/2 M_t (g_t^2 - g_t'^2) in every regime (the
  // sticking case is the handout's -1/2 M_n (1 - e^2) g_n^2 - 1/2 M_t g_t^2), and dE <= 0.
  const Real e0 = energy(a) + energy(b), e1 = energy(a2) + energy(b2);
  const Real eScale = e0 + e1;
  EXPECT_LE(e1 - e0, kTol * eScale) << "energy must not increase";
  truth_test::record("energy non-increase", std::max<Real>(0, (e1 - e0) / eScale));
  const Real predicted =
      -0.5L * (g.gn * g.gn - g2.gn * g2.gn) / invMn - 0.5L * (g.gt * g.gt - g2.gt * g2.gt) / invMt;
  EXPECT_CLOSE("energy change (effective masses)", e1 - e0, predicted, eScale);

  switch (out.regime) {
    case Regime::Smooth:
      ++counts.smooth;
      EXPECT_EQ(k.mu, 0);
      EXPECT_CLOSE("smooth: J_t = 0", out.tangentImpulse, 0, speed / invMn);
      EXPECT_CLOSE("smooth: spin unchanged", a2.w * a.radius, a.w * a.radius, speed);
      EXPECT_CLOSE("smooth: tangential velocity unchanged", dot(vel(a2), tau), dot(vel(a), tau),
                   speed);
      break;
    case Regime::Sticking:
      ++counts.sticking;
      EXPECT_GT(k.mu, 0);
      EXPECT_CLOSE("sticking: g_t' = 0", g2.gt, 0, speed);
      EXPECT_CLOSE("sticking: J_t = -M_t g_t", out.tangentImpulse, -g.gt / invMt, speed / invMn);
      EXPECT_LE(std::fabs(out.tangentImpulse), k.mu * out.normalImpulse * (1 + kTol))
          << "inside the Coulomb cone";
      if (std::isinf(k.mu)) {
        EXPECT_CLOSE("no-slip (mu = inf): g_t' = 0", g2.gt, 0, speed);
      }
      break;
    case Regime::Sliding:
      ++counts.sliding;
      EXPECT_TRUE(k.mu > 0 && std::isfinite(k.mu));
      EXPECT_CLOSE("sliding: |J_t| = mu J_n", std::fabs(out.tangentImpulse),
                   k.mu * out.normalImpulse, speed / invMn);
      EXPECT_LT(out.tangentImpulse * g.gt, 0) << "friction opposes the slip";
      EXPECT_GE(g2.gt * g.gt, 0) << "sliding cannot reverse the slip";
      EXPECT_LT(std::fabs(g2.gt), std::fabs(g.gt));
      // Sticking would have needed more than the cone allows.
      EXPECT_GT(std::fabs(g.gt) / invMt, k.mu * out.normalImpulse * (1 - kTol));
      break;
    case Regime::Separating:
      ADD_FAILURE() << "approaching bodies reported as separating";
      break;
  }
}

TEST(TruthInvariants, RandomDiscPairs) {
  Rng rng(20240601);
  Counts counts;
  for (int i = 0; i < 20000; ++i) {
    const Case k = randomCase(rng, false);
    SCOPED_TRACE(i);
    checkCase(k, counts);
    if (HasFailure()) break;  // one case is enough to read; don't flood the log
  }
  // Every regime must have been exercised many times.
  EXPECT_GT(counts.separating, 1000);
  EXPECT_GT(counts.smooth, 500);
  EXPECT_GT(counts.sticking, 1000);
  EXPECT_GT(counts.sliding, 1000);
  std::printf("[ truth   ] disc pairs: %d separating, %d smooth, %d sticking, %d sliding\n",
              counts.separating, counts.smooth, counts.sticking, counts.sliding);
}

TEST(TruthInvariants, RandomDiscOnWall) {
  Rng rng(7);
  Counts counts;
  for (int i = 0; i < 20000; ++i) {
    const Case k = randomCase(rng, true);
    SCOPED_TRACE(i);
    checkCase(k, counts);
    if (HasFailure()) break;
  }
  EXPECT_GT(counts.separating, 1000);
  EXPECT_GT(counts.smooth, 500);
  EXPECT_GT(counts.sticking, 1000);
  EXPECT_GT(counts.sliding, 1000);
  std::printf("[ truth   ] disc on wall: %d separating, %d smooth, %d sticking, %d sliding\n",
              counts.separating, counts.smooth, counts.sticking, counts.sliding);
}

// A wall is the limit of a disc at rest whose mass goes to infinity. With m_b = 1e15 and
// J_b = m_b r_b^2 / 2, the heavy disc adds 1/m_b to 1/M_n and 1/m_b + r_b^2/J_b = 3/m_b to 1/M_t.
// For the light disc (J_a = m_a r_a^2 / 2, so M_t <= m_a/3 against the wall):
//   dJ_n / m_a ~ J_n (M_n/m_b) / m_a <= (1 + e)|g_n| m_a/m_b <= 2 |g_n| m_a/m_b,
//   dJ_t / m_a ~ J_t (3 M_t/m_b) / m_a <= |g_t| m_a/(3 m_b)  (sticking; sliding: J_t < M_t|g_t|
//   and dJ_t = mu dJ_n is smaller still), and the spin moves by r_a^2 dJ_t/J_a = 2 dJ_t/m_a.
// So velocities and impulses differ by at most 2 m_a/m_b relative to the speed scale (which
// bounds |g_n| and |g_t|); the heavy disc itself moves by O(impulse/m_b). Tolerance:
// 4 m_a/m_b + kTol (<= 5e-15 with m_a <= 1). The result is continuous across the stick/slip
// boundary, so a regime flip would not matter; none occurs with this seed (compared too).
TEST(TruthInvariants, WallIsTheLimitOfAnInfinitelyHeavyDisc) {
  Rng rng(99);
  int compared = 0;
  for (int i = 0; i < 5000; ++i) {
    Case k = randomCase(rng, true);
    k.a.mass = rng.logUniform(0.1L, 1);
    k.a.inertia = 0.5L * k.a.mass * k.a.radius * k.a.radius;
    Body heavy;
    heavy.mass = 1e15L;
    heavy.radius = k.b.radius;
    heavy.inertia = 0.5L * heavy.mass * heavy.radius * heavy.radius;
    const Impact toWall = solveImpact(k.a, k.b, k.nx, k.ny, k.e, k.mu);
    const Impact toHeavy = solveImpact(k.a, heavy, k.nx, k.ny, k.e, k.mu);
    SCOPED_TRACE(i);
    ASSERT_EQ(toWall.regime, toHeavy.regime);
    if (toWall.regime == Regime::Separating) continue;
    ++compared;
    const Real speed = std::hypot(k.a.vx, k.a.vy) + k.a.radius * std::fabs(k.a.w);
    const Real tol = 4 * k.a.mass / heavy.mass + kTol;
    auto near = [&](const char* what, Real x, Real y, Real scale) {
      const Real rel = std::fabs(x - y) / scale;
      truth_test::record("wall = limit of 1e15 kg disc", rel);
      EXPECT_LE(rel, tol) << what;
    };
    near("v_x", toHeavy.a.vx, toWall.a.vx, speed);
    near("v_y", toHeavy.a.vy, toWall.a.vy, speed);
    near("w r", toHeavy.a.w * k.a.radius, toWall.a.w * k.a.radius, speed);
    near("J_n", toHeavy.normalImpulse, toWall.normalImpulse, k.a.mass * speed);
    near("J_t", toHeavy.tangentImpulse, toWall.tangentImpulse, k.a.mass * speed);
    // The heavy disc barely moves: |dv_b| <= |J| / m_b <= 2 m_a speed / m_b.
    EXPECT_LE(std::hypot(toHeavy.b.vx, toHeavy.b.vy), 3 * k.a.mass * speed / heavy.mass);
    EXPECT_LE(std::fabs(toHeavy.b.w) * heavy.radius, 4 * k.a.mass * speed / heavy.mass);
    if (HasFailure()) break;
  }
  EXPECT_GT(compared, 2000);
}

}  // namespace
