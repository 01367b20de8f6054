// The Pareto front and the equal-error ratio on hand-built sweeps.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "particles/timestep/pareto.h"

namespace particles::timestep {
namespace {

TEST(Pareto, KeepsOnlyUnbeatenPointsSortedByTime) {
  // (2, 0.1) is beaten by (1, 0.05); (3, inf) diverged; (4, 0.01) and (8, 0.001) stay.
  const double inf = std::numeric_limits<double>::infinity();
  const auto front = paretoFront(
      {{2, 0.1, 0}, {1, 0.05, 1}, {3, inf, 2}, {8, 0.001, 3}, {4, 0.01, 4}, {9, 0.01, 5}});
  ASSERT_EQ(front.size(), 3u);
  EXPECT_EQ(front[0].index, 1u);
  EXPECT_EQ(front[1].index, 4u);
  EXPECT_EQ(front[2].index, 3u);
}

// Between (1 s, 1e-2) and (100 s, 1e-4), log-log linear: error 1e-3 is
// halfway in log, so the time is 10 s.
TEST(Pareto, InterpolatesInLogLog) {
  const std::vector<CostPoint> front{{1, 1e-2, 0}, {100, 1e-4, 1}};
  EXPECT_NEAR(timeAtError(front, 1e-3)->seconds, 10.0, 1e-12);
  EXPECT_FALSE(timeAtError(front, 1e-3)->clamped);
  EXPECT_EQ(timeAtError(front, 1.0)->seconds, 1.0);
  EXPECT_TRUE(timeAtError(front, 1.0)->clamped);
  EXPECT_FALSE(timeAtError(front, 1e-5).has_value());
}

// Engine: t = 1e-2 / error (1 s at 1e-2, 100 s at 1e-4). Box2D: ten times
// slower at every error, over 1e-1..1e-3. The tightest common error is
// 1e-3: engine 10 s, Box2D 100 s, ratio 10.
TEST(Pareto, EqualErrorRatioAtTheTightestCommonError) {
  const std::vector<CostPoint> engine{{1, 1e-2, 0}, {100, 1e-4, 1}};
  const std::vector<CostPoint> box2d{{1, 1e-1, 0}, {100, 1e-3, 1}};
  const auto r = equalErrorRatio(engine, box2d);
  ASSERT_TRUE(r.has_value());
  EXPECT_DOUBLE_EQ(r->error, 1e-3);
  EXPECT_NEAR(r->engineSeconds, 10.0, 1e-12);
  EXPECT_NEAR(r->box2dSeconds, 100.0, 1e-12);
  EXPECT_NEAR(r->ratio, 10.0, 1e-12);
  EXPECT_FALSE(r->engineClamped || r->box2dClamped);
}

// An engine exact at its cheapest point (error 0, floored to 1e-16) against
// a Box2D whose best is 1e-5 at 4 s: the engine's time there is clamped to
// its cheapest, 0.5 s, so the ratio 8 is a lower bound.
TEST(Pareto, ExactEngineGivesABound) {
  const std::vector<CostPoint> engine{{0.5, 0.0, 0}};
  const std::vector<CostPoint> box2d{{1, 1e-3, 0}, {4, 1e-5, 1}};
  const auto r = equalErrorRatio(engine, box2d);
  ASSERT_TRUE(r.has_value());
  EXPECT_DOUBLE_EQ(r->error, 1e-5);
  EXPECT_DOUBLE_EQ(r->ratio, 8.0);
  EXPECT_TRUE(r->engineClamped);
  EXPECT_FALSE(r->box2dClamped);
}

}  // namespace
}  // namespace particles::timestep
