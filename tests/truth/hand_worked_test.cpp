// Hand-worked impacts: every expected number below is derived in the comment next to it, from
// momentum, angular momentum about the contact point and the contact laws - never copied from
// the program's output. Tolerance: kTol = 1e-15 relative to the velocity (or impulse) scale of
// the case (see truth_test_util.h).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "particles/truth/closed_form.h"
#include "truth_test_util.h"

namespace {

using particles::truth::Body;
using particles::truth::Impact;
using particles::truth::Regime;
using particles::truth::solveImpact;
using truth_test::Real;

constexpr Real kInf = std::numeric_limits<Real>::infinity();

Body disc(Real m, Real J, Real r, Real vx, Real vy, Real w) {
  return Body{m, J, r, vx, vy, w};
}
Body wall() {
  Body b;
  b.wall = true;
  return b;
}

void expectState(const Body& got, Real vx, Real vy, Real w, Real scale) {
  EXPECT_CLOSE("hand-worked velocity", got.vx, vx, scale);
  EXPECT_CLOSE("hand-worked velocity", got.vy, vy, scale);
  EXPECT_CLOSE("hand-worked spin", got.w, w, scale);
}

void expectImpulse(const Impact& got, Real jn, Real jt, Real scale) {
  EXPECT_CLOSE("hand-worked impulse", got.normalImpulse, jn, scale);
  EXPECT_CLOSE("hand-worked impulse", got.tangentImpulse, jt, scale);
}

// Two equal discs (m = 1, r = 1, J = m r^2 / 2 = 0.5), n = (1, 0), e = 1, mu = 0.
// g_n = v_bx - v_ax = -1 - 2 = -3 < 0: approaching.
// Normal: momentum 1*2 + 1*(-1) = 1 and, for e = 1, kinetic energy along x conserved; with
// equal masses the x velocities exchange: v_ax' = -1, v_bx' = 2 (check: g_n' = 3 = -e g_n).
// Smooth: no tangential impulse, so v_y and (angular momentum about c, no lever along y) the
// spins are unchanged. Impulse on b: J_n = m_b (2 - (-1)) = 3, J_t = 0.
TEST(TruthHandWorked, HeadOnEqualMassesElasticSmoothExchangeVelocities) {
  const Body a = disc(1, 0.5L, 1, 2, 0.5L, 3);
  const Body b = disc(1, 0.5L, 1, -1, -0.25L, -1);
  const Impact out = solveImpact(a, b, 1, 0, 1, 0);
  EXPECT_EQ(out.regime, Regime::Smooth);
  expectState(out.a, -1, 0.5L, 3, 3);
  expectState(out.b, 2, -0.25L, -1, 3);
  expectImpulse(out, 3, 0, 3);
}

// e = 0, mu = 0: both leave with the common (centre-of-mass) normal velocity.
// m_a = 2, v_a = 2 n; m_b = 1, v_b = -n: v' = (2*2 + 1*(-1)) / 3 = 1 along n.
// J_n = m_b (1 - (-1)) = 2. Done along x and along n = (0.6, 0.8) (the result is then n itself,
// with v_a = (1.2, 1.6), v_b = (-0.6, -0.8)).
TEST(TruthHandWorked, PerfectlyInelasticGivesCommonVelocity) {
  {
    const Impact out = solveImpact(disc(2, 1, 1, 2, 0, 0), disc(1, 0.5L, 1, -1, 0, 0), 1, 0, 0, 0);
    EXPECT_EQ(out.regime, Regime::Smooth);
    expectState(out.a, 1, 0, 0, 2);
    expectState(out.b, 1, 0, 0, 2);
    expectImpulse(out, 2, 0, 2);
  }
  {
    const Impact out = solveImpact(disc(2, 1, 1, 1.2L, 1.6L, 0), disc(1, 0.5L, 1, -0.6L, -0.8L, 0),
                                   0.6L, 0.8L, 0, 0);
    EXPECT_EQ(out.regime, Regime::Smooth);
    expectState(out.a, 0.6L, 0.8L, 0, 2);
    expectState(out.b, 0.6L, 0.8L, 0, 2);
    expectImpulse(out, 2, 0, 2);
  }
}

// Ball a on a floor (wall b below it): n = (0, -1) from the ball to the floor, tau = z x n =
// (1, 0). Write v_t = v_x, v_n = v_y. The ball's contact point (c - x = r n = (0, -r)) moves at
// v + w z x (0, -r) = (v_t + w r, v_n), so g_t = -(v_t + w r) and g_n = v_n.
// Sticking derivation. Let X be the tangential (x) impulse on the ball. Then
// dv_t = X/m and dw = ((c - x) x (X, Y)) / J = (0*Y - (-r) X)/J = r X / J. No slip after:
// v_t + X/m + (w + r X/J) r = 0  =>  X = -(v_t + w r) / (1/m + r^2/J) = -m q (v_t + w r)/(1 + q),
// q = J / (m r^2). Hence
//   v_t' = v_t - q (v_t + w r)/(1 + q) = (v_t - q w r)/(1 + q),
//   w'   = w + r X / J = w - (v_t + w r)/((1 + q) r)          (since m q r / J = 1/r).
// Numbers: m = 2, r = 0.5, J = m r^2/2 = 0.25, q = 0.5, v = (3, -4), w = 2 (w r = 1), e = 0.5.
//   v_t' = (3 - 0.5)/1.5 = 5/3;  w' = 2 - 4/(1.5*0.5) = 2 - 16/3 = -10/3  (v_t' + w' r = 0 ok);
//   v_n' = -e v_n = 2;
//   impulse on the ball = m dv = 2 (5/3 - 3, 2 + 4) = (-8/3, 12); on the wall (b) = (8/3, -12)
//   = J_n n + J_t tau with J_n = 12, J_t = 8/3. Coulomb: sticking iff mu >= (8/3)/12 = 2/9.
TEST(TruthHandWorked, BallOnFloorSticking) {
  const Body ball = disc(2, 0.25L, 0.5L, 3, -4, 2);
  for (const Real mu : {0.5L, 2.0L / 9 * (1 + 1e-9L), kInf}) {
    SCOPED_TRACE(static_cast<double>(mu));
    const Impact out = solveImpact(ball, wall(), 0, -1, 0.5L, mu);
    EXPECT_EQ(out.regime, Regime::Sticking);
    expectState(out.a, 5.0L / 3, 2, -10.0L / 3, 4);
    expectImpulse(out, 12, 8.0L / 3, 12);
    EXPECT_TRUE(out.b.wall);
    EXPECT_EQ(out.b.vx, 0);
  }
}

// Same ball, mu = 0.1 < 2/9: sliding. The friction on the ball opposes the slip of its contact
// point, s = sign(v_t + w r) = +1, with magnitude mu times the normal impulse m (1 + e)|v_n|:
//   v_t' = v_t - mu (1 + e)|v_n| s            = 3 - 0.1*1.5*4 = 3 - 0.6 = 2.4,
//   w'   = w - mu (1 + e)|v_n| s m r / J      = w - mu (1 + e)|v_n| s / (q r)
//                                             = 2 - 0.6/(0.5*0.5) = 2 - 2.4 = -0.4,
//   v_n' = 2;  J_n = 12, J_t = mu J_n = 1.2 (on the wall, along +tau: it opposes g_t = -4 < 0).
// The slip keeps its sign: v_t' + w' r = 2.4 - 0.2 = 2.2 > 0.
TEST(TruthHandWorked, BallOnFloorSliding) {
  const Body ball = disc(2, 0.25L, 0.5L, 3, -4, 2);
  const Impact out = solveImpact(ball, wall(), 0, -1, 0.5L, 0.1L);
  EXPECT_EQ(out.regime, Regime::Sliding);
  expectState(out.a, 2.4L, 2, -0.4L, 4);
  expectImpulse(out, 12, 1.2L, 12);
  // mu = 2/9 (1 - 1e-9): just sliding; J_t = mu J_n = 8/3 (1 - 1e-9).
  const Impact edge = solveImpact(ball, wall(), 0, -1, 0.5L, 2.0L / 9 * (1 - 1e-9L));
  EXPECT_EQ(edge.regime, Regime::Sliding);
  EXPECT_CLOSE("hand-worked impulse", edge.tangentImpulse, 8.0L / 3 * (1 - 1e-9L), 12);
}

// The floor again with the roles swapped: the wall is a and the ball is b, n = (0, 1) from the
// wall up to the ball, tau = (-1, 0). Same physics, so the ball ends as above; the impulse on
// the ball (b) is (-8/3, 12) = J_n n + J_t tau with J_n = 12, J_t = 8/3 (the same numbers).
TEST(TruthHandWorked, WallAsBodyA) {
  const Body ball = disc(2, 0.25L, 0.5L, 3, -4, 2);
  const Impact out = solveImpact(wall(), ball, 0, 1, 0.5L, 0.5L);
  EXPECT_EQ(out.regime, Regime::Sticking);
  EXPECT_TRUE(out.a.wall);
  expectState(out.b, 5.0L / 3, 2, -10.0L / 3, 4);
  expectImpulse(out, 12, 8.0L / 3, 12);
}

// Regime boundary between two different discs.
// a: m = 1, r = 1, J = 0.5;  b: m = 3, r = 0.5, J = 0.4*3*0.25 = 0.3 (solid sphere); e = 0.5,
// mu = 0.4, n = (0.6, 0.8). Effective masses:
//   M_n = (1/1 + 1/3)^-1 = 0.75,
//   M_t = (1/m_a + 1/m_b + r_a^2/J_a + r_b^2/J_b)^-1 = (1 + 1/3 + 2 + 5/6)^-1 = (25/6)^-1 = 0.24.
// Sticking needs J_t = -M_t g_t and J_n = M_n (1 + e)|g_n|, so it holds iff
//   |g_t|/|g_n| <= mu (1 + e) M_n / M_t = 0.4*1.5*0.75/0.24 = 1.875.
// With v_b = 0, w_b = 0, v_a = 2 n + k tau, w_a = 0: g_n = -2, g_t = -k; critical k = 3.75.
// Sliding (k > 3.75): J_n = 0.75*1.5*2 = 2.25, J_t = +mu J_n = 0.9 (s = -sign(g_t) = +1);
//   dv_b = (2.25 n + 0.9 tau)/3 = 0.75 n + 0.3 tau,  dv_a = -(2.25 n + 0.9 tau),
//   dw_b = -r_b J_t / J_b = -0.5*0.9/0.3 = -1.5,     dw_a = -r_a J_t / J_a = -0.9/0.5 = -1.8,
//   (lever arms: c - x_b = -r_b n, c - x_a = +r_a n, and n x tau = 1),
//   so dg_t = 0.3 + 0.9 + 0.5*1.5 + 1*1.8 = 3.75 and g_t' = 3.75 - k (< 0: slip not reversed).
// Sticking (k < 3.75): J_t = 0.24 k, J_n = 2.25, g_t' = 0.
TEST(TruthHandWorked, RegimeBoundaryBetweenTwoDiscs) {
  const Real nx = 0.6L, ny = 0.8L, tx = -ny, ty = nx;
  const Body b = disc(3, 0.3L, 0.5L, 0, 0, 0);
  for (const Real sign : {1.0L, -1.0L}) {  // slip of either sign: J_t flips with it
    SCOPED_TRACE(static_cast<double>(sign));
    const Real below = sign * 3.75L * (1 - 1e-9L), above = sign * 3.75L * (1 + 1e-9L);
    const Impact stick = solveImpact(disc(1, 0.5L, 1, 2 * nx + below * tx, 2 * ny + below * ty, 0),
                                     b, nx, ny, 0.5L, 0.4L);
    EXPECT_EQ(stick.regime, Regime::Sticking);
    expectImpulse(stick, 2.25L, 0.24L * below, 2.25L);
    const Impact slide = solveImpact(disc(1, 0.5L, 1, 2 * nx + above * tx, 2 * ny + above * ty, 0),
                                     b, nx, ny, 0.5L, 0.4L);
    EXPECT_EQ(slide.regime, Regime::Sliding);
    expectImpulse(slide, 2.25L, sign * 0.9L, 2.25L);
    expectState(slide.b, 0.75L * nx + sign * 0.3L * tx, 0.75L * ny + sign * 0.3L * ty, sign * -1.5L,
                4);
    expectState(slide.a, (2 - 2.25L) * nx + (above - sign * 0.9L) * tx,
                (2 - 2.25L) * ny + (above - sign * 0.9L) * ty, sign * -1.8L, 4);
  }
  // The same boundary reached through spin instead of sliding velocity: v_a = 2 n, w_a = -k/r_a
  // gives g_t = -w_a r_a = k > 0, so J_t < 0.
  const Impact spun =
      solveImpact(disc(1, 0.5L, 1, 2 * nx, 2 * ny, -3.75L * (1 + 1e-9L)), b, nx, ny, 0.5L, 0.4L);
  EXPECT_EQ(spun.regime, Regime::Sliding);
  expectImpulse(spun, 2.25L, -0.9L, 2.25L);
  const Impact spunStick =
      solveImpact(disc(1, 0.5L, 1, 2 * nx, 2 * ny, -3.75L * (1 - 1e-9L)), b, nx, ny, 0.5L, 0.4L);
  EXPECT_EQ(spunStick.regime, Regime::Sticking);
  expectImpulse(spunStick, 2.25L, -0.24L * 3.75L * (1 - 1e-9L), 2.25L);
}

// Handout thought experiment 1: equal discs head-on with equal spins.
// m = 1, r = 1, J = 0.5, n = (1, 0), tau = (0, 1), v_a = (1, 0), v_b = (-1, 0), w_a = w_b = 3.
// g_n = -2, g_t = 0 - 3*1 - 3*1 = -6. M_n = 1/2, M_t = (1 + 1 + 2 + 2)^-1 = 1/6.
// e = 1, no slip: J_n = (1/2)(2)(2) = 2, J_t = -M_t g_t = 1.
//   v_b' = v_b + (J_n, J_t)/m = (1, 1), v_a' = (-1, -1): equal and opposite sideways velocities;
//   w_a' - w_a = -r J_t/J = -2 = w_b' - w_b: equal spin changes, w' = 1 for both.
// Check: g_t' = (1 - (-1)) - 1 - 1 = 0.
// With mu = 0.3 < J_t/J_n = 1/2 it slides: J_t = 0.3*2 = 0.6, sideways +-0.6, dw = -1.2 each.
TEST(TruthHandWorked, EqualSpinsHeadOnGiveOppositeSidewaysVelocities) {
  const Body a = disc(1, 0.5L, 1, 1, 0, 3), b = disc(1, 0.5L, 1, -1, 0, 3);
  const Impact noSlip = solveImpact(a, b, 1, 0, 1, kInf);
  EXPECT_EQ(noSlip.regime, Regime::Sticking);
  expectState(noSlip.a, -1, -1, 1, 3);
  expectState(noSlip.b, 1, 1, 1, 3);
  expectImpulse(noSlip, 2, 1, 2);

  const Impact slide = solveImpact(a, b, 1, 0, 1, 0.3L);
  EXPECT_EQ(slide.regime, Regime::Sliding);
  expectState(slide.a, -1, -0.6L, 3 - 1.2L, 3);
  expectState(slide.b, 1, 0.6L, 3 - 1.2L, 3);
  expectImpulse(slide, 2, 0.6L, 2);
}

// Handout thought experiment 2: opposite spins (meshing gears). w_a = 3, w_b = -3:
// g_t = 0 - (-3)(1) - 3(1) = 0, the surfaces already move together at the contact, so no
// tangential impulse is needed for any mu > 0: spins and sideways velocities are unchanged,
// only the normal velocities exchange (e = 1).
TEST(TruthHandWorked, OppositeSpinsGearsNeedNoTangentialImpulse) {
  const Body a = disc(1, 0.5L, 1, 1, 0, 3), b = disc(1, 0.5L, 1, -1, 0, -3);
  for (const Real mu : {0.3L, kInf}) {
    const Impact out = solveImpact(a, b, 1, 0, 1, mu);
    EXPECT_EQ(out.regime, Regime::Sticking);
    expectState(out.a, -1, 0, 3, 3);
    expectState(out.b, 1, 0, -3, 3);
    expectImpulse(out, 2, 0, 2);
  }
}

// Separating or grazing bodies: nothing happens, bit for bit.
TEST(TruthHandWorked, SeparatingBodiesAreUnchanged) {
  const Body a = disc(1, 0.5L, 1, -1, 2, 5), b = disc(2, 1, 1, 0.5L, -3, -4);
  for (const Real vbx : {0.5L, -1.0L}) {  // g_n = 1.5 (separating), g_n = 0 (grazing)
    Body bb = b;
    bb.vx = vbx;
    const Impact out = solveImpact(a, bb, 1, 0, 0.5L, kInf);
    EXPECT_EQ(out.regime, Regime::Separating);
    EXPECT_EQ(out.a.vx, a.vx);
    EXPECT_EQ(out.a.vy, a.vy);
    EXPECT_EQ(out.a.w, a.w);
    EXPECT_EQ(out.b.vx, bb.vx);
    EXPECT_EQ(out.b.vy, bb.vy);
    EXPECT_EQ(out.b.w, bb.w);
    EXPECT_EQ(out.normalImpulse, 0);
    EXPECT_EQ(out.tangentImpulse, 0);
  }
  // A ball rising off the floor (v_y = +1, n = (0, -1): g_n = v_y = 1 > 0).
  const Impact off = solveImpact(disc(1, 0.5L, 1, 3, 1, 2), wall(), 0, -1, 1, kInf);
  EXPECT_EQ(off.regime, Regime::Separating);
  EXPECT_EQ(off.a.vy, 1);
  EXPECT_EQ(off.a.w, 2);
}

TEST(TruthHandWorked, RejectsInvalidInput) {
  const Body a = disc(1, 0.5L, 1, 1, 0, 0), b = disc(1, 0.5L, 1, -1, 0, 0);
  EXPECT_THROW(solveImpact(wall(), wall(), 1, 0, 1, 0), std::invalid_argument);
  EXPECT_THROW(solveImpact(disc(0, 0.5L, 1, 1, 0, 0), b, 1, 0, 1, 0), std::invalid_argument);
  EXPECT_THROW(solveImpact(disc(1, 0, 1, 1, 0, 0), b, 1, 0, 1, 0), std::invalid_argument);
  EXPECT_THROW(solveImpact(disc(1, 0.5L, -1, 1, 0, 0), b, 1, 0, 1, 0), std::invalid_argument);
  EXPECT_THROW(solveImpact(a, b, 1, 1, 1, 0), std::invalid_argument);  // |n| = sqrt 2
  EXPECT_THROW(solveImpact(a, b, 1, 0, 1.5L, 0), std::invalid_argument);
  EXPECT_THROW(solveImpact(a, b, 1, 0, -0.1L, 0), std::invalid_argument);
  EXPECT_THROW(solveImpact(a, b, 1, 0, 1, -1), std::invalid_argument);
  EXPECT_THROW(solveImpact(a, b, 1, 0, 1, std::nanl("")), std::invalid_argument);
  EXPECT_NO_THROW(solveImpact(a, b, 1, 0, 1, kInf));
}

}  // namespace
