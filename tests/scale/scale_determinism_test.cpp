// The large-scene path gives the same bits for any thread count (issue 5):
// the same pile stepped with 1, 2 and 3 threads ends in the same state hash,
// whatever the height of the bands of its Gauss-Seidel order.
// Also: it is engaged only from SolverSettings::scaleThreshold on, so a
// smaller scene keeps the step of docs/physics.md.
#include <gtest/gtest.h>

#include <cstdint>

#include "particles/pile/pile_scene.h"
#include "particles/state_hash.h"
#include "particles/world.h"

namespace particles::pile {
namespace {

// bandRows < 0: SolverSettings' default; else bands of that height from
// bandsFrom balls (by default at this size too). fastCells < 0: the default
// reach of the fast pairs' search.
std::uint64_t hashAfter(int threads, int steps, bool poly, int bandRows = -1, int bandsFrom = 0,
                        bool wavefront = true, int fastCells = -1) {
  PileParams p;
  p.count = 2500;
  p.polydisperse = poly;
  p.threads = threads;
  SceneDef scene = makePile(p);
  scene.solver.scaleParallelFrom = 0;  // share the step among the threads at this size too
  if (bandRows >= 0) {
    scene.solver.scaleBandRows = bandRows;
    scene.solver.scaleBandsFrom = bandsFrom;
  }
  scene.solver.scaleWavefront = wavefront;
  if (fastCells >= 0) scene.solver.scaleFastPairCells = fastCells;
  World world(scene);
  EXPECT_TRUE(world.plan().scale);
  world.run(steps);
  return stateHash(world);
}

TEST(ScaleDeterminism, SameHashWithOneTwoAndThreeThreads) {
  for (bool poly : {false, true}) {
    // 240 steps: the pile has landed and contacts are warm-started.
    const std::uint64_t one = hashAfter(1, 240, poly);
    EXPECT_EQ(hashAfter(2, 240, poly), one) << "poly " << poly;
    EXPECT_EQ(hashAfter(3, 240, poly), one) << "poly " << poly;
  }
}

// The threads order their work by waiting for each other only where their
// strips meet (docs/scale.md, "Bands"): whole strips (0), bands of one grid
// row (the most phases) and of five, each the same for 1, 2 and 3 threads,
// and each a sweep of its own (the order changes the bits).
TEST(ScaleDeterminism, SameHashForAnyThreadCountWithAnyBandHeight) {
  std::uint64_t previous = 0;
  for (int bandRows : {0, 1, 5}) {
    const std::uint64_t one = hashAfter(1, 120, false, bandRows);
    EXPECT_EQ(hashAfter(2, 120, false, bandRows), one) << "band rows " << bandRows;
    EXPECT_EQ(hashAfter(3, 120, false, bandRows), one) << "band rows " << bandRows;
    EXPECT_NE(one, previous) << "band rows " << bandRows;
    previous = one;
  }
}

// The velocity passes as a wavefront over the bands (pass p on band j after
// pass p - 1 on band j + lag; docs/scale.md, "Passes as a wavefront") give
// the bits of whole passes one after another: bands of one, two and five
// grid rows, fast pairs reaching two or four cells (rows between bands
// further apart: a larger lag), 120 steps (landing, with fast pairs) and
// 300 (settled, with the settle iteration), one and two threads. Checked by
// hand that the test sees the order: a lag of 0 (every pass of a band
// before the next band), or one band less than bandReach_ with bands of
// one row, changes the hash.
TEST(ScaleDeterminism, WavefrontGivesTheBitsOfWholePasses) {
  struct Case {
    int bandRows, fastCells, steps;
  };
  for (const auto [bandRows, fastCells, steps] :
       {Case{1, 2, 120}, Case{1, 4, 120}, Case{2, 2, 120}, Case{2, 2, 300}, Case{5, 2, 120}}) {
    const std::uint64_t whole = hashAfter(1, steps, false, bandRows, 0, false, fastCells);
    EXPECT_EQ(hashAfter(1, steps, false, bandRows, 0, true, fastCells), whole)
        << "band rows " << bandRows << ", fast cells " << fastCells << ", steps " << steps;
    EXPECT_EQ(hashAfter(2, steps, false, bandRows, 0, true, fastCells), whole)
        << "band rows " << bandRows << ", fast cells " << fastCells << ", steps " << steps;
  }
}

// Bands start at SolverSettings::scaleBandsFrom balls: below it the sweep is
// that of whole strips whatever scaleBandRows says (the 10,000 pile and the
// golden scenes keep their bits), from it the bands change the sweep.
TEST(ScaleDeterminism, BandsStartAtTheirBallCount) {
  // hashAfter's pile has 2,500 balls.
  const std::uint64_t wholeStrips = hashAfter(1, 120, false, 0);
  const std::uint64_t fromItsCount = hashAfter(1, 120, false, 2, 2500);
  EXPECT_EQ(hashAfter(1, 120, false, 2, 2501), wholeStrips);
  EXPECT_EQ(fromItsCount, hashAfter(1, 120, false, 2, 0));
  EXPECT_NE(fromItsCount, wholeStrips);
}

TEST(ScaleDeterminism, CopiedWorldContinuesIdentically) {
  PileParams p;
  p.count = 1500;
  p.threads = 2;
  SceneDef scene = makePile(p);
  scene.solver.scaleParallelFrom = 0;
  World original(scene);
  original.run(150);
  World copy = original;  // carries the warm-start impulses, not the threads
  original.run(50);
  copy.run(50);
  EXPECT_EQ(stateHash(copy), stateHash(original));
}

TEST(ScaleDeterminism, PathEngagesOnlyFromTheThreshold) {
  PileParams p;
  p.count = 1000;
  SceneDef scene = makePile(p);
  scene.gravity = Vec2::Zero();  // a gas: the large path from scaleThreshold balls
  scene.balls.resize(999);
  EXPECT_FALSE(World(scene).plan().scale);
  scene.balls.resize(1000);
  EXPECT_TRUE(World(scene).plan().scale);
  scene.solver.mutation = Mutation::NormalImpulseSign;  // mutants stay on the small path
  EXPECT_FALSE(World(scene).plan().scale);
  // Under gravity (a pile): from scaleThresholdUnderGravity balls.
  p.count = 31;
  EXPECT_FALSE(World(makePile(p)).plan().scale);
  p.count = 32;
  EXPECT_TRUE(World(makePile(p)).plan().scale);
}

}  // namespace
}  // namespace particles::pile
