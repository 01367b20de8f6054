// A state the large-scene path cannot step in bounded memory (step_error.h):
// balls heaped into each other far beyond touching, as after a blow-up. The
// step stops with StepError before it makes the rows, instead of taking the
// machine's memory (docs/scale.md, "A state that cannot be stepped"), and
// it stops for any thread count, as every result of the path does not
// depend on it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "large_path_scene.h"
#include "particles/world.h"

namespace particles {
namespace {

// `count` balls of radius 0.5 m whose centres lie within a square of side
// 1 cm: every pair overlaps by 0.99 m or more, count^2 / 2 rows.
SceneDef heap(int count, int threads) {
  SceneDef s = test::largePathScene(1.0 / 60.0, 10.0, {-20.0, -20.0}, {20.0, 20.0});
  s.solver.threads = threads;
  s.solver.scaleParallelFrom = 0;  // the threads share the step at this size too
  for (int k = 0; k < count; ++k) {
    BallDef b;
    b.position = {0.01 * (k % 37) / 37.0, 0.01 * (k % 41) / 41.0};
    b.radius = 0.5;
    b.mass = 1.0;
    s.balls.push_back(b);
  }
  return s;
}

TEST(ScaleStepError, BallsHeapedIntoEachOtherStopTheStepForAnyThreadCount) {
  // 3,000 balls: 4.5 million pairs, 1,500 rows a ball, 23 times the bound
  // of 64 (equal radii).
  for (int threads : {1, 2, 3}) {
    World world(heap(3000, threads));
    try {
      world.step();
      FAIL() << threads << " threads: the step made its rows";
    } catch (const StepError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("more than 64 contact rows a ball"), std::string::npos) << what;
      EXPECT_NE(what.find("for 3000 balls"), std::string::npos) << what;
    }
  }
}

TEST(ScaleStepError, TheWorldIsLeftAsTheFailedStepFoundItWithItsForcesApplied) {
  const SceneDef scene = heap(3000, 2);
  World world(scene);
  EXPECT_THROW(world.step(), StepError);
  // Nothing moved and no step was counted; gravity's push of this step
  // (g dt straight down, from rest) is in the velocities, as step_error.h
  // says.
  EXPECT_EQ(world.stepIndex(), 0);
  const std::vector<BallState> balls = world.balls();
  for (std::size_t i = 0; i < balls.size(); ++i) {
    EXPECT_EQ(balls[i].position, scene.balls[i].position) << i;
    EXPECT_EQ(balls[i].velocity, Vec2(scene.dt * scene.gravity)) << i;
  }
  // Stepping on meets the same state and stops again.
  EXPECT_THROW(world.step(), StepError);
}

TEST(ScaleStepError, AHeapWithinTheBoundIsStepped) {
  // 100 balls heaped the same way: 4,950 rows, under 64 a ball (6,400).
  // Nothing throws, and the overlap passes push the heap apart.
  World world(heap(100, 2));
  world.step();
  EXPECT_EQ(world.stats().contacts, 100 * 99 / 2);
}

TEST(ScaleStepError, ABoulderInFineSandIsStepped) {
  // A valid scene whose radii differ 100-fold: 1,521 grains of 1 cm, 1 mm
  // apart, and a boulder of 1 m beside them. The margin (0.2 of the largest
  // radius, 0.2 m) puts up to about 350 grains within reach of a grain (136
  // rows a ball were measured, the grains at the edges having fewer): over
  // the bound for equal radii (64), which stopped this valid scene, but not
  // over the bound for this spread (64 x 100^2).
  SceneDef s = test::largePathScene(1.0 / 60.0, 10.0, {-5.0, -5.0}, {5.0, 5.0});
  constexpr int kSide = 39;
  for (int i = 0; i < kSide * kSide; ++i) {
    BallDef b;
    b.position = {-2.0 + 0.021 * (i % kSide), -4.0 + 0.021 * (i / kSide)};
    b.radius = 0.01;
    b.mass = 1e-3;
    s.balls.push_back(b);
  }
  BallDef boulder;
  boulder.position = {3.0, -3.0};
  boulder.radius = 1.0;
  boulder.mass = 10.0;
  s.balls.push_back(boulder);
  World world(s);
  EXPECT_NO_THROW(world.step());
  const double rowsPerBall = static_cast<double>(world.stats().contacts) / 1522.0;
  EXPECT_GT(rowsPerBall, 64.0);  // the case the spread is for
  EXPECT_LT(rowsPerBall, 400.0);
}

}  // namespace
}  // namespace particles
