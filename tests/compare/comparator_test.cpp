// The comparator measures what it claims to measure, attributes constructed
// discrepancies to the cause that was built into them, and catches every
// mutant of the solver.
#include <gtest/gtest.h>

#include <cmath>

#include "particles/compare/attribution.h"
#include "particles/compare/case_generator.h"
#include "particles/compare/invariants.h"
#include "particles/compare/suite.h"
#include "particles/compare/suite_report.h"

namespace particles::compare {
namespace {

ImpactCase namedCase(const std::string& name) {
  for (const ImpactCase& c : catalogue())
    if (c.name == name) return c;
  ADD_FAILURE() << "no catalogue case " << name;
  return {};
}

reference::Box2DSettings settingsFor(const ImpactCase& c) {
  return reference::Box2DSettings::forScene(c.scene);
}

TEST(Discrepancy, MeasuresAHandMadeDifference) {
  // Two equal balls of radius 0.5 head-on at 2 m/s each with spins 5 and 5:
  // the speed scale is |v| + |w| r = 2 + 2.5 = 4.5 m/s.
  const ImpactCase c = namedCase("catalogue/head-on, same spins");
  Outcome x = initialState(c), y = initialState(c);
  y.balls[1].velocity += Vec2(0.3, -0.4);  // |dv| = 0.5 m/s
  y.balls[0].angularVelocity -= 2.0;       // |dw| = 2 rad/s, times r = 1 m/s
  const Discrepancy d = measureDiscrepancy(c, x, y);
  EXPECT_DOUBLE_EQ(d.velocity, 0.5);
  EXPECT_DOUBLE_EQ(d.spin, 2.0);
  EXPECT_DOUBLE_EQ(d.relative, 1.0 / 4.5);
}

TEST(Discrepancy, NonFiniteNeverAgrees) {
  const ImpactCase c = namedCase("catalogue/head-on, same spins");
  Outcome x = initialState(c), y = initialState(c);
  y.balls[0].velocity.x() = std::nan("");
  y.finite = false;
  EXPECT_TRUE(std::isinf(measureDiscrepancy(c, x, y).relative));
}

TEST(Invariants, TruthBreaksNoneAndAHandMadeErrorBreaksMomentum) {
  const ImpactCase c = randomCase(Family::NoSlip, 7, 3);
  const Outcome truth = *runTruth(c);
  EXPECT_TRUE(violatedInvariants(measureInvariants(c, truth), toleranceFor(Source::Truth)).empty());
  Outcome wrong = truth;
  wrong.balls[1].velocity *= 1.01;  // ball b gains 1 % of its momentum from nowhere
  const auto broken = violatedInvariants(measureInvariants(c, wrong), toleranceFor(Source::Truth));
  EXPECT_NE(std::find(broken.begin(), broken.end(), "momentum"), broken.end());
}

TEST(Invariants, EnergyGrowthIsReported) {
  const ImpactCase c = namedCase("catalogue/head-on, elastic, smooth");
  Outcome faster = *runTruth(c);
  faster.balls[0].velocity *= 1.1;
  faster.balls[1].velocity *= 1.1;  // momentum still 0, energy up 21 %
  const Invariants inv = measureInvariants(c, faster);
  EXPECT_NEAR(inv.energyChange, 0.21, 1e-12);
  const auto broken = violatedInvariants(inv, toleranceFor(Source::Engine));
  EXPECT_NE(std::find(broken.begin(), broken.end(), "energy growth"), broken.end());
}

TEST(Attribution, OneVelocityIterationIsTooFew) {
  // Box2D solves friction before the normal impulse: with one iteration a new
  // contact's friction is clamped by a zero normal impulse, so an oblique
  // no-slip hit gets no tangential impulse at all.
  const ImpactCase c = namedCase("catalogue/floor, oblique, no-slip");
  reference::Box2DSettings s = settingsFor(c);
  s.velocityIterations = 1;
  const Attribution a = attributeBox2D(c, *runTruth(c), runBox2D(c, s), s);
  EXPECT_EQ(a.cause, Cause::VelocityIterations) << a.detail;
}

TEST(Attribution, SlowApproachBelowTheRestitutionThreshold) {
  // A 3 m/s approach with e = 0.5 and Box2D's threshold at 5 m/s: Box2D
  // stops the ball instead of bouncing it.
  const ImpactCase c = namedCase("catalogue/floor, oblique, sliding");
  reference::Box2DSettings s = settingsFor(c);
  s.restitutionThreshold = 5.0;
  const Attribution a = attributeBox2D(c, *runTruth(c), runBox2D(c, s), s);
  EXPECT_EQ(a.cause, Cause::RestitutionThreshold) << a.detail;
}

TEST(Attribution, DeepOverlapMovesBox2DsContactPoint) {
  // Start a no-slip, spinning hit with the surfaces 5 cm into each other:
  // Box2D's contact point sits in the middle of the overlap, 2.5 cm inside
  // each surface, which shortens both lever arms and changes the spins.
  ImpactCase c = namedCase("catalogue/head-on, same spins");
  c.scene.balls[0].position.x() += 0.025;
  c.scene.balls[1].position.x() -= 0.025;
  const reference::Box2DSettings s = settingsFor(c);
  const Attribution a = attributeBox2D(c, *runTruth(c), runBox2D(c, s), s);
  EXPECT_EQ(a.cause, Cause::MidOverlapContact) << a.detail;
}

TEST(Attribution, SizesOutsideBox2DsRangeAreNotEngineErrors) {
  // A 1 cm ball is below the 0.1-10 m Box2D is tuned for (and its 5 mm
  // linear slop is half the radius).
  ImpactCase c = namedCase("catalogue/floor, oblique, no-slip");
  c.scene.balls[0].radius = 0.01;
  c.scene.balls[0].position.y() = 0.01 * (1.0 - kPlacementOverlap);
  const reference::Box2DSettings s = settingsFor(c);
  const Attribution a = attributeBox2D(c, *runTruth(c), runBox2D(c, s), s);
  EXPECT_EQ(a.cause, Cause::OutsideRange) << a.detail;
}

TEST(Attribution, NewtonsCradleIsAboutTheOrderOfImpulses) {
  // The engine passes the momentum down the row one exchange at a time, so
  // the last ball leaves with it; Box2D solves the touching contacts
  // together and spreads it. Both conserve momentum; neither is a bug.
  const ImpactCase c = namedCase("catalogue/Newton's cradle, 3 balls");
  const reference::Box2DSettings s = settingsFor(c);
  const Outcome engine = runEngine(c);
  EXPECT_NEAR(engine.balls[2].velocity.x(), 2.0, 1e-12);
  const Attribution a = attributeBox2D(c, engine, runBox2D(c, s), s);
  EXPECT_EQ(a.cause, Cause::SequentialOrder) << a.detail;
}

TEST(Attribution, AgreementNeedsNoCause) {
  const ImpactCase c = namedCase("catalogue/floor, oblique, sticking");
  const reference::Box2DSettings s = settingsFor(c);
  EXPECT_EQ(attributeBox2D(c, *runTruth(c), runBox2D(c, s), s).cause, Cause::Agrees);
}

TEST(Mutants, EveryMutantIsCaught) {
  SuiteSettings s;
  s.casesPerFamily = 20;
  s.mutantCasesPerFamily = 20;
  s.jobs = 2;
  const SuiteResult r = runSuite(s);
  ASSERT_EQ(r.mutants.size(), kAllMutations.size());
  for (const MutantRecord& m : r.mutants)
    EXPECT_TRUE(m.caught) << mutationName(m.mutation) << " was not caught";
  EXPECT_EQ(r.mutantCatchRate(), 1.0);
}

TEST(Mutants, TheUnmutatedEngineIsNeverFlagged) {
  SuiteSettings s;
  s.casesPerFamily = 200;
  s.mutants = false;
  const SuiteResult r = runSuite(s);
  for (const CaseRecord& c : r.cases) EXPECT_TRUE(c.engineOk) << c.kase.name;
}

TEST(Suite, ReportIsTheSameWhateverTheThreadCount) {
  SuiteSettings s;
  s.casesPerFamily = 100;
  s.mutantCasesPerFamily = 10;
  s.jobs = 1;
  SuiteResult one = runSuite(s);
  s.jobs = 2;
  SuiteResult two = runSuite(s);
  nlohmann::json a = suiteJson(one, CaseRecords::All), b = suiteJson(two, CaseRecords::All);
  a.erase("timing");
  b.erase("timing");
  EXPECT_EQ(a.dump(), b.dump());
}

TEST(Cases, RandomCasesDependOnlyOnSeedFamilyAndIndex) {
  const ImpactCase a = randomCase(Family::Wall, 42, 17);
  const ImpactCase b = randomCase(Family::Wall, 42, 17);
  const ImpactCase c = randomCase(Family::Wall, 43, 17);
  EXPECT_EQ(a.scene.balls[0].velocity, b.scene.balls[0].velocity);
  EXPECT_NE(a.scene.balls[0].velocity, c.scene.balls[0].velocity);
}

TEST(Cases, BodiesStartAtContactAndApproaching) {
  for (Family f : kAllFamilies) {
    for (int i = 0; i < 200; ++i) {
      const ImpactCase c = randomCase(f, 1, i);
      if (!c.isolated) continue;
      const BallDef& a = c.scene.balls[0];
      if (c.scene.walls.empty()) {
        const BallDef& b = c.scene.balls[1];
        const double gap = (b.position - a.position).norm() - (a.radius + b.radius);
        EXPECT_NEAR(gap, -kPlacementOverlap * (a.radius + b.radius), 1e-12 * (a.radius + b.radius));
        EXPECT_LT((b.velocity - a.velocity).dot(b.position - a.position), 0.0) << c.name;
      } else {
        // The wall passes through the origin along the contact tangent.
        EXPECT_NEAR(a.position.norm(), a.radius * (1.0 - kPlacementOverlap), 1e-12 * a.radius);
        // n = -x / |x| points from the ball to the wall: approaching is v . n > 0.
        EXPECT_GT(a.velocity.dot(-a.position), 0.0) << c.name;
      }
    }
  }
}

TEST(Cases, FrictionFamiliesLandInTheirRegime) {
  // The generator picks mu below (sliding) or above (sticking) the case's
  // threshold; the closed form's verdict must agree.
  for (int i = 0; i < 300; ++i) {
    const ImpactCase sliding = randomCase(Family::FrictionSliding, 1, i);
    const Invariants s = measureInvariants(sliding, *runTruth(sliding));
    EXPECT_NEAR(std::abs(s.tangentImpulse), sliding.params.friction * s.normalImpulse,
                1e-9 * (std::abs(s.normalImpulse) + std::abs(s.tangentImpulse)))
        << sliding.name;
    const ImpactCase sticking = randomCase(Family::FrictionSticking, 1, i);
    const Invariants t = measureInvariants(sticking, *runTruth(sticking));
    EXPECT_LT(std::abs(t.tangentImpulse), sticking.params.friction * t.normalImpulse)
        << sticking.name;
  }
}

}  // namespace
}  // namespace particles::compare
