// The time-stepped catalogue's closed forms: the floor bounce against the
// long-double truth, and the engine at small dt against every analytic answer.
#include <gtest/gtest.h>

#include <cmath>

#include "particles/timestep/catalogue.h"
#include "particles/timestep/floor_bounce.h"
#include "particles/truth/closed_form.h"

namespace particles::timestep {
namespace {

void expectMatchesTruth(double vx, double vy, double w, double e, double mu, bool sticking) {
  const double r = 0.5, m = 2.0, q = 0.5;
  truth::Body disc{m, q * m * r * r, r, vx, vy, w, false};
  truth::Body floor;
  floor.wall = true;
  const truth::Impact t = truth::solveImpact(disc, floor, 0.0L, -1.0L, e, mu);
  const FloorBounce f = floorBounce(vx, vy, w, r, q, e, mu);
  EXPECT_EQ(f.sticking, sticking);
  EXPECT_EQ(t.regime == truth::Regime::Sticking, sticking);
  const double scale = std::fabs(vx) + std::fabs(vy) + std::fabs(w) * r;
  EXPECT_NEAR(f.vx, static_cast<double>(t.a.vx), 1e-14 * scale);
  EXPECT_NEAR(f.vy, static_cast<double>(t.a.vy), 1e-14 * scale);
  EXPECT_NEAR(f.w * r, static_cast<double>(t.a.w) * r, 1e-14 * scale);
}

// Sticking limit |vx + w r| <= mu (1 + e) |vy| (1 + q) / q = 3 mu (1 + e) |vy|.
TEST(FloorBounce, SlidingAndStickingAgreeWithTheTruth) {
  expectMatchesTruth(2.0, -1.0, 5.0, 0.5, 0.2, false);   // slip 4.5 > 0.9: sliding
  expectMatchesTruth(-2.0, -1.0, 1.0, 0.5, 0.2, false);  // slip -1.5, |.| > 0.9
  expectMatchesTruth(0.5, -1.0, 0.5, 0.5, 0.2, true);    // slip 0.75 <= 0.9: sticking
  expectMatchesTruth(1.0, -2.0, -3.0, 1.0, 0.4, true);   // slip -0.5
  expectMatchesTruth(3.0, -1.0, 0.0, 0.0, INFINITY, true);
}

// The catalogue scene's bounce is the sliding case, and leaves the floor
// with vy = 0.5 and the slip reduced but not reversed.
TEST(FloorBounce, CatalogueCaseIsSliding) {
  const FloorBounce f = floorBounce(2.0, -1.0, 5.0, 0.5, 0.5, 0.5, 0.2);
  EXPECT_FALSE(f.sticking);
  EXPECT_DOUBLE_EQ(f.vy, 0.5);
  EXPECT_DOUBLE_EQ(f.vx, 2.0 - 0.2 * 1.5);        // 1.7
  EXPECT_DOUBLE_EQ(f.w, 5.0 - 0.2 * 1.5 / 0.25);  // 3.8
  EXPECT_GT(f.vx + f.w * 0.5, 0.0);
}

double engineError(const std::string& name, double dt) {
  const TimestepScene t = catalogueScene(name);
  const SceneDef s = withStep(t.scene, dt);
  auto stepper = engineStepper(s);
  auto metric = t.metric({});
  return measure(*stepper, *metric, s.stepCount());
}

// At dt = 1e-4 the engine meets each closed form within a first-order bound
// C dt written out per scene, and the error shrinks as dt does (first order:
// at least 4x smaller for a 10x smaller step).
struct Case {
  const char* name;
  double bound;  // at dt = 1e-4
};
class EngineMeetsClosedForms : public ::testing::TestWithParam<Case> {};

TEST_P(EngineMeetsClosedForms, WithinAFirstOrderBound) {
  const Case c = GetParam();
  const double fine = engineError(c.name, 1e-4), coarse = engineError(c.name, 1e-3);
  RecordProperty("error_dt_1e-4", std::to_string(fine));
  EXPECT_LE(fine, c.bound) << c.name;
  EXPECT_LE(fine, coarse / 4.0 + 1e-12) << c.name << " coarse " << coarse;
}

// Bounds (dt = 1e-4 s):
//  bounce: each of 3 bounces can misplace the ball by at most one step of
//    travel at the impact speed sqrt(2 g h0) = 4.43 m/s (the contact is seen
//    up to a step late, the projection lifts it), plus g dt^2 of apex
//    sampling: 3 * 4.43e-4 / h0 = 1.3e-3.
//  slide_roll: the roll starts within one step of t* = 0.34 s, and semi-
//    implicit Euler's friction impulse mu m g dt per step makes vf exact:
//    2 dt / t* = 5.9e-4.
//  incline_roll: semi-implicit Euler's a t dt / 2 over a T^2 / 2 is dt / T
//    = 1e-4, doubled for the first contact step: 2e-4.
//  oblique_spin: the impact is seen up to a step late, so the position is
//    off by up to |v| dt = 2.2e-4 m, divided by r = 0.5: 4.5e-4.
//  pull: symplectic Euler's phase error omega^2 dt T / 2 = 4 * 1e-4 * 2 / 2
//    = 4e-4 in position, and the velocity is half a step off, omega dt / 2:
//    4e-4 + 1e-4 = 5e-4.
INSTANTIATE_TEST_SUITE_P(Catalogue, EngineMeetsClosedForms,
                         ::testing::Values(Case{"bounce", 1.3e-3}, Case{"slide_roll", 5.9e-4},
                                           Case{"incline_roll", 2e-4}, Case{"oblique_spin", 4.5e-4},
                                           Case{"pull", 5e-4}),
                         [](const auto& info) { return std::string(info.param.name); });

// The cradle with e = 1 and mu = 0 transmits the momentum through the row
// within the first step (Gauss-Seidel passes in index order): exact to
// rounding at any dt. The last ball's x (up to 5 m) gathers one rounding of
// at most 2^-52 * 5 m per step over 500 steps, divided by the 1 m length scale.
TEST(EngineMeetsClosedFormsExactly, Cradle) {
  EXPECT_LE(engineError("cradle", 1e-3), 500 * 0x1.0p-52 * 5.0);
}

// Elastic smooth impacts conserve energy exactly and the projection never
// touches velocities: the gas's drift is rounding over ~1e4 impacts.
TEST(EngineMeetsClosedFormsExactly, GasEnergy) {
  EXPECT_LE(engineError("gas", 1e-3), 1e-12);
}

TEST(TimestepCatalogue, EveryReferenceSceneHasAnObservable) {
  for (const TimestepScene& t : catalogue()) {
    if (t.kind != MetricKind::ConvergedReference) continue;
    EXPECT_GT(t.referenceDt, 0.0) << t.name;
    EXPECT_LE(t.referenceDt, t.scene.dt / 10) << t.name;  // "far smaller": at least 10x
    EXPECT_TRUE(static_cast<bool>(t.observable)) << t.name;
  }
  EXPECT_EQ(catalogue().size(), 9u);
}

}  // namespace
}  // namespace particles::timestep
