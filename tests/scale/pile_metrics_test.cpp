// The pile figures on hand-built configurations whose answers are known.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "particles/pile/pile_metrics.h"

namespace particles::pile {
namespace {

BallDef disk(double x, double radius, double mass = 1.0) {
  BallDef d;
  d.position = Vec2(x, 0.0);
  d.radius = radius;
  d.mass = mass;
  return d;
}

std::vector<BallState> statesOf(const std::vector<BallDef>& defs) {
  std::vector<BallState> s;
  for (const BallDef& d : defs) s.push_back({d.position, d.velocity, 0.0, d.angularVelocity});
  return s;
}

TEST(PileMetrics, OverlapIsAFractionOfTheSmallerRadius) {
  const std::vector<BallDef> defs = {
      disk(0.0, 0.5),   disk(0.9, 0.5),    // 0.1 m deep, smaller r 0.5: 20 %
      disk(10.0, 0.25), disk(10.65, 0.5),  // 0.1 m deep, smaller r 0.25: 40 %
      disk(20.0, 0.5),  disk(21.0, 0.5),   // just touching: 0 %
      disk(30.0, 0.5),  disk(31.5, 0.5),   // apart: not a touching pair
  };
  const OverlapFigures f = measureOverlap(statesOf(defs), defs);
  EXPECT_EQ(f.touchingPairs, 3);
  EXPECT_NEAR(f.max, 0.4, 1e-12);
  EXPECT_NEAR(f.mean, (0.2 + 0.4 + 0.0) / 3, 1e-12);
}

TEST(PileMetrics, NoTouchingPairsMeansNoOverlap) {
  const std::vector<BallDef> defs = {disk(0.0, 0.5), disk(2.0, 0.5)};
  const OverlapFigures f = measureOverlap(statesOf(defs), defs);
  EXPECT_EQ(f.touchingPairs, 0);
  EXPECT_EQ(f.max, 0.0);
  EXPECT_EQ(f.mean, 0.0);
}

// Enough disks for the grid: a row of 100 disks 0.95 m apart, each pair
// overlapping 0.05 m = 10 % of 0.5 m.
TEST(PileMetrics, OverlapOfALongRow) {
  std::vector<BallDef> defs;
  for (int i = 0; i < 100; ++i) defs.push_back(disk(0.95 * i, 0.5));
  const OverlapFigures f = measureOverlap(statesOf(defs), defs);
  EXPECT_EQ(f.touchingPairs, 99);
  EXPECT_NEAR(f.max, 0.1, 1e-12);
  EXPECT_NEAR(f.mean, 0.1, 1e-12);
}

TEST(PileMetrics, KineticEnergyCountsTranslationAndSpin) {
  BallDef a = disk(0.0, 0.5, 2.0);
  a.velocity = Vec2(3.0, 4.0);  // 1/2 2 25 = 25 J
  a.angularVelocity = 2.0;      // J = 1/2 2 0.25 = 0.25 kg m^2: 1/2 0.25 4 = 0.5 J
  BallDef b = disk(5.0, 1.0, 1.0);
  b.inertia = 3.0;
  b.angularVelocity = -1.0;  // 1/2 3 1 = 1.5 J
  const std::vector<BallDef> defs = {a, b};
  EXPECT_DOUBLE_EQ(kineticEnergy(statesOf(defs), defs), 27.0);
}

// Border points are inside; a NaN centre is outside (it is nowhere in the box).
TEST(PileMetrics, OutsideCountsCentresBeyondTheBox) {
  const Vec2 lo(0.0, 0.0), hi(10.0, 20.0);
  auto at = [](double x, double y) { return BallState{Vec2(x, y), Vec2::Zero(), 0.0, 0.0}; };
  const std::vector<BallState> in = {at(0.0, 0.0), at(10.0, 20.0), at(5.0, 7.0)};
  EXPECT_EQ(countOutside(in, lo, hi), 0);
  const std::vector<BallState> out = {at(-0.04, 5.0), at(5.0, -1e-9), at(10.5, 5.0),
                                      at(5.0, 20.1),  at(5.0, 5.0),   at(NAN, 5.0)};
  EXPECT_EQ(countOutside(out, lo, hi), 5);
}

TEST(PileMetrics, RestEnergyIsAllTheMassAtTheRestSpeed) {
  const std::vector<BallDef> defs = {disk(0.0, 0.5, 2.0), disk(5.0, 0.5, 6.0)};
  EXPECT_DOUBLE_EQ(restEnergy(defs), 0.5 * 8.0 * 0.01 * 0.01);
}

TEST(PileMetrics, RestStepIsWhereTheEnergyStaysBelow) {
  const std::vector<double> settling = {5.0, 0.5, 2.0, 0.1, 0.05};
  EXPECT_EQ(restStep(settling, 1.0), 3);
  const std::vector<double> moving = {0.1, 0.1, 2.0};
  EXPECT_EQ(restStep(moving, 1.0), std::nullopt);
  const std::vector<double> still = {0.1, 0.2};
  EXPECT_EQ(restStep(still, 1.0), 0);
  EXPECT_EQ(restStep(std::vector<double>{}, 1.0), std::nullopt);
}

}  // namespace
}  // namespace particles::pile
