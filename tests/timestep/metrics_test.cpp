// Each metric fed a hand-built motion whose error is known by construction.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "particles/timestep/metrics.h"

namespace particles::timestep {
namespace {

BallState at(double x, double y, double vx = 0, double vy = 0, double w = 0) {
  return {{x, y}, {vx, vy}, 0.0, w};
}

double run(std::vector<Frame> frames, Metric& m) {
  RecordedStepper s(std::move(frames));
  const long long steps = static_cast<long long>(s.frameCount()) - 1;
  return measure(s, m, steps);
}

// Arcs whose highest samples are 1 % above e^{2k} h0: the worst error is 1 %
// of the first apex, e^2 h0 * 0.01, divided by h0.
TEST(TimestepMetrics, ApexHeightsReadsTheTopOfEachArc) {
  const double r = 0.5, e = 0.8, h0 = 1.0;
  std::vector<Frame> f{{0.0, {at(0, r + h0)}}};
  double t = 0.0;
  for (int k = 1; k <= 3; ++k) {
    const double h = 1.01 * std::pow(e, 2 * k) * h0;
    f.push_back({t += 0.1, {at(0, r + 0.01, 0, -3)}});     // falling onto the floor
    f.push_back({t += 0.1, {at(0, r + 0.5 * h, 0, 2)}});   // rising
    f.push_back({t += 0.1, {at(0, r + h, 0, 0.1)}});       // the top
    f.push_back({t += 0.1, {at(0, r + 0.9 * h, 0, -1)}});  // falling: the arc ends
  }
  auto m = apexHeights(0, 0.0, r, e, h0, 3);
  EXPECT_NEAR(run(f, *m), 0.01 * e * e, 1e-12);
}

TEST(TimestepMetrics, ApexHeightsCountsAMissingApexAsTheWholeHeight) {
  std::vector<Frame> f{{0.0, {at(0, 1.5)}}, {0.1, {at(0, 0.5, 0, -4)}}};
  auto m = apexHeights(0, 0.0, 0.5, 0.8, 1.0, 1);
  EXPECT_EQ(run(f, *m), 1.0);
}

// v0 = 3, mu = 0.3, g = 10, q = 1/2: t* = 3 / (0.3 * 10 * 3) = 1/3 s, vf = 2.
// Rolling is first seen at 0.4 s (20 % late) and the final speed is 2.02 (1 %).
TEST(TimestepMetrics, SlideToRollTakesTheWorseOfTimeAndSpeed) {
  const double r = 0.5;
  std::vector<Frame> f{{0.0, {at(0, r, 3.0)}},
                       {0.2, {at(0.5, r, 2.6, 0, -2.0)}},        // slip 1.6: sliding
                       {0.4, {at(1.0, r, 2.02, 0, -2.02 / r)}},  // slip 0: rolling
                       {0.6, {at(1.4, r, 2.02, 0, -2.02 / r)}}};
  auto m = slideToRoll(0, 3.0, r, 0.5, 0.3, 10.0);
  EXPECT_NEAR(run(f, *m), 0.2, 1e-12);
}

// Same disk, samples at 0, 0.3 s (slip 3 - 9 * 0.3 = 0.3) and 0.4 s (rolling):
// the slip line reaches 0 at 0.3 + 0.3 * 0.3 / 2.7 = 1/3 s = t* exactly, so
// only the final speed 2.01 (0.5 % above vf = 2) counts.
TEST(TimestepMetrics, SlideToRollFindsTheRollingTimeBetweenSamples) {
  const double r = 0.5;
  std::vector<Frame> f{{0.0, {at(0, r, 3.0)}},
                       {0.3, {at(0.6, r, 2.1, 0, -3.6)}},         // slip 2.1 - 1.8 = 0.3
                       {0.4, {at(0.8, r, 2.01, 0, -2.01 / r)}}};  // rolling
  auto m = slideToRoll(0, 3.0, r, 0.5, 0.3, 10.0);
  EXPECT_NEAR(run(f, *m), 0.005, 1e-12);
}

TEST(TimestepMetrics, SlideToRollThatNeverRollsCountsAsOne) {
  std::vector<Frame> f{{0.0, {at(0, 0.5, 3.0)}}, {0.5, {at(1, 0.5, 2.9)}}};
  auto m = slideToRoll(0, 3.0, 0.5, 0.5, 0.3, 10.0);
  EXPECT_EQ(run(f, *m), 1.0);
}

// s(t) = 1.05 a t^2 / 2 along (3, 4)/5: the error is 5 % of a T^2 / 2.
TEST(TimestepMetrics, ConstantAccelerationRelativeToTheFinalDistance) {
  const double a = 2.0;
  const Vec2 dir(0.6, 0.8);
  std::vector<Frame> f;
  for (int k = 0; k <= 10; ++k) {
    const double t = 0.1 * k, s = 1.05 * 0.5 * a * t * t;
    f.push_back({t, {BallState{Vec2(1, 1) + s * dir, Vec2::Zero(), 0, 0}}});
  }
  auto m = constantAcceleration(0, Vec2(3, 4), a);
  EXPECT_NEAR(run(f, *m), 0.05, 1e-12);
}

// A trajectory 0.01 m off the exact one (length scale 0.5: 0.02) with a
// speed 0.03 m/s off (scale 1: 0.03) and a spin 0.1 rad/s off (r = 0.5,
// scale 1: 0.05): the worst of the three.
TEST(TimestepMetrics, ExactTrajectoryTakesTheWorstComponent) {
  ExactState exact = [](double t) { return BallState{{t, 0}, {1, 0}, 0, 0}; };
  std::vector<Frame> f{
      {0.0, {at(0, 0, 1)}}, {0.5, {at(0.51, 0, 1.03, 0, 0.1)}}, {1.0, {at(1, 0, 1)}}};
  auto m = exactTrajectory(0, exact, 0.5, 0.5, 1.0);
  EXPECT_NEAR(run(f, *m), 0.05, 1e-12);
}

// A bounce at t = 0.5 s: v = +1 before, -1 after. A sample at exactly 0.5 s
// with either velocity is right; 0.1 s later only the new one is.
TEST(TimestepMetrics, ExactTrajectoryAcceptsEitherSideOfAnImpact) {
  ExactState exact = [](double t) {
    return t <= 0.5 ? BallState{{t, 0}, {1, 0}, 0, 0} : BallState{{1 - t, 0}, {-1, 0}, 0, 0};
  };
  std::vector<Frame> before{{0.0, {at(0, 0, 1)}}, {0.5, {at(0.5, 0, 1)}}};
  std::vector<Frame> after{{0.0, {at(0, 0, 1)}}, {0.5, {at(0.5, 0, -1)}}};
  std::vector<Frame> late{{0.0, {at(0, 0, 1)}}, {0.5, {at(0.5, 0, 1)}}, {0.6, {at(0.6, 0, 1)}}};
  auto m1 = exactTrajectory(0, exact, 0.5, 1.0, 1.0, {0.5});
  auto m2 = exactTrajectory(0, exact, 0.5, 1.0, 1.0, {0.5});
  auto m3 = exactTrajectory(0, exact, 0.5, 1.0, 1.0, {0.5});
  EXPECT_EQ(run(before, *m1), 0.0);
  // (the "just after" exact position is 1 - nextafter(0.5), one rounding off)
  EXPECT_NEAR(run(after, *m2), 0.0, 1e-15);
  EXPECT_NEAR(run(late, *m3), 2.0, 1e-12);  // |dv| = 2 at 0.6 s (|dx| = 0.2)
}

TEST(TimestepMetrics, ExactFinalStateReadsOnlyTheLastSample) {
  std::vector<BallState> exact{at(1, 0), at(2, 0, 1)};
  std::vector<Frame> f{{0.0, {at(5, 5), at(5, 5)}}, {1.0, {at(1, 0), at(2.1, 0, 1)}}};
  auto m = exactFinalState(exact, {0.5, 0.5}, 1.0, 1.0);
  EXPECT_NEAR(run(f, *m), 0.1, 1e-12);
}

// E(0) = 1/2 * 2 * 1^2 + 1/2 * 1 * 0^2 = 1 J; later 1.03 J and 0.99 J: 3 %.
TEST(TimestepMetrics, EnergyDriftIsTheLargestRelativeChange) {
  const double v = std::sqrt(1.03);
  std::vector<Frame> f{
      {0.0, {at(0, 0, 1)}}, {0.1, {at(0, 0, v)}}, {0.2, {at(0, 0, std::sqrt(0.99))}}};
  auto m = energyDrift({2.0}, {1.0});
  EXPECT_NEAR(run(f, *m), 0.03, 1e-12);
}

TEST(TimestepMetrics, ReferenceMatchComparesTheFinalObservable) {
  Observable y = [](const Stepper& s) { return std::vector<double>{s.ball(0).position.y()}; };
  std::vector<Frame> f{{0.0, {at(0, 9)}}, {1.0, {at(0, 1.25)}}};
  auto m = referenceMatch(y, {1.0}, 0.5);
  EXPECT_NEAR(run(f, *m), 0.5, 1e-12);
}

TEST(TimestepMetrics, NonFiniteStateIsInfiniteError) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Frame> f{{0.0, {at(0, 0, 1)}}, {1.0, {at(nan, 0, 1)}}};
  auto m = energyDrift({1.0}, {1.0});
  EXPECT_TRUE(std::isinf(run(f, *m)));
}

}  // namespace
}  // namespace particles::timestep
