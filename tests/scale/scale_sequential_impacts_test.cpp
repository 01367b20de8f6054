// SolverSettings::scaleSequentialImpacts: the large path's rigid step solves
// a group of impacts that meet within one step (and nothing else) as the
// sequence of pairwise impacts, in the order of their times of impact
// (docs/scale.md, "Impacts in sequence"). Checked against a sequence worked
// out by hand, against the elastic gas's energy, and for the same bits on
// any thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "hard_disk_gas.h"
#include "particles/state_hash.h"
#include "particles/world.h"

namespace particles::test {
namespace {

BallDef disk(double x, double v, double mass) {
  BallDef b;
  b.position = {x, 0.0};
  b.velocity = {v, 0.0};
  b.radius = 0.5;
  b.mass = mass;
  return b;
}

// A (1 kg, +1 m/s), B (2 kg, at rest) and C (1 kg, -1 m/s) on a line, B 0.01
// m from A and 0.02 m from C: within one step of 0.2 s both pairs close, A and
// B first. Elastic, smooth. The sequence, by the one-dimensional elastic
// impact v1' = ((m1 - m2) v1 + 2 m2 v2) / (m1 + m2):
//   A-B: A -1/3, B 2/3;  B-C: B -4/9, C 11/9;  A-B again (B now leaves A
//   behind at 1/9 m/s, closing the 0.01 m within the step): A -13/27,
//   B -10/27; then every pair parts.
// Momentum 0 and energy 1 J before and after. The velocity passes alone give
// both pairs their bounce at once instead.
TEST(ScaleSequentialImpacts, ThreeBallsMeetAsThePairwiseSequence) {
  SceneDef s;
  s.dt = 0.2;
  s.contact = {1.0, 0.0};
  s.solver.scaleThreshold = 0;  // the large path at three balls
  s.solver.scaleSequentialImpacts = true;
  s.balls = {disk(0.0, 1.0, 1.0), disk(1.01, 0.0, 2.0), disk(2.03, -1.0, 1.0)};
  World w(s);
  ASSERT_TRUE(w.plan().scale);
  w.step();
  EXPECT_EQ(w.stats().sequentialGroups, 1);
  EXPECT_NEAR(w.ball(0).velocity.x(), -13.0 / 27.0, 1e-14);
  EXPECT_NEAR(w.ball(1).velocity.x(), -10.0 / 27.0, 1e-14);
  EXPECT_NEAR(w.ball(2).velocity.x(), 33.0 / 27.0, 1e-14);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(w.ball(i).velocity.y(), 0.0);
    EXPECT_EQ(w.ball(i).angularVelocity, 0.0);
  }

  s.solver.scaleSequentialImpacts = false;
  World passes(s);
  passes.step();
  EXPECT_EQ(passes.stats().sequentialGroups, 0);
  EXPECT_GT(std::abs(passes.ball(0).velocity.x() + 13.0 / 27.0), 1e-3);
}

// Energy over 8 s of the elastic gas (hard_disk_gas.h) at area fraction phi
// and step dt: the relative loss; with the replay, whether every step left no
// group to the passes and kept the energy to rounding (3,600 kinetic energies
// summed: a few 1e-16 each). Also the groups replayed.
struct GasRun {
  double lost = 0.0;
  long long replayed = 0;
};
GasRun runGas(double phi, double dt, bool sequential) {
  HardDiskGas gas = hardDiskGas(60, phi, 1.0, dt, 1.0, 3);
  gas.scene.solver.scaleSequentialImpacts = sequential;
  World world(gas.scene);
  const double E0 = temperature(world.balls());
  GasRun out;
  double before = E0;
  for (long long k = 0; k < std::lround(8.0 / dt); ++k) {
    world.step();
    const double after = temperature(world.balls());
    out.replayed += world.stats().sequentialGroups;
    if (sequential) {
      // No gravity, no forces: no contact carries a load, so no group is
      // left to the passes.
      EXPECT_EQ(world.stats().sequentialGroupsLeft, 0) << "step " << k;
      EXPECT_LE(std::abs(after - before), 1e-13 * E0) << "step " << k << ", dt " << dt;
    }
    before = after;
  }
  out.lost = (E0 - before) / E0;
  return out;
}

// With the passes alone the gas loses 1-12.5 % over 8 s (ScaleGas.*,
// docs/scale.md); with the groups in sequence it keeps its energy to
// rounding, step by step and over the 480-1,920 steps (each within 1e-13).
TEST(ScaleSequentialImpacts, ElasticGasKeepsItsEnergy) {
  for (const auto& [phi, dt] :
       {std::pair{0.3, 1.0 / 60.0}, std::pair{0.3, 1.0 / 240.0}, std::pair{0.45, 1.0 / 60.0}}) {
    const GasRun passes = runGas(phi, dt, false);
    const GasRun sequence = runGas(phi, dt, true);
    EXPECT_EQ(passes.replayed, 0);
    EXPECT_GT(sequence.replayed, 10) << "phi " << phi << ", dt " << dt;
    EXPECT_GT(passes.lost, 0.01) << "phi " << phi << ", dt " << dt;
    EXPECT_LE(std::abs(sequence.lost), 1e-10) << "phi " << phi << ", dt " << dt;
  }
}

// Under gravity a touching contact may carry a load: a stack of three balls
// resting on the floor is one group of touching rows, left to the passes (the
// warm start and the support sweep hold it up), so the step is bit for bit
// the passes' alone.
TEST(ScaleSequentialImpacts, ALoadedStackIsLeftToThePasses) {
  SceneDef s;
  s.dt = 1.0 / 60.0;
  s.gravity = {0.0, -10.0};
  s.contact = {0.5, 0.5};
  s.walls = boxWalls({-5.0, 0.0}, {5.0, 10.0});
  s.solver.scaleThreshold = 0;
  s.solver.scaleThresholdUnderGravity = 0;
  for (int k = 0; k < 3; ++k) {
    BallDef b;
    b.position = {0.0, 0.5 + k};
    b.radius = 0.5;
    b.mass = 1.0;
    s.balls.push_back(b);
  }
  World passes(s);
  s.solver.scaleSequentialImpacts = true;
  World sequence(s);
  ASSERT_TRUE(sequence.plan().scale);
  for (int k = 0; k < 120; ++k) {
    passes.step();
    sequence.step();
  }
  EXPECT_EQ(sequence.stats().sequentialGroups, 0);
  EXPECT_EQ(sequence.stats().sequentialGroupsLeft, 1);
  EXPECT_EQ(stateHash(sequence), stateHash(passes));
}

// One thread replays the groups, in the order of their first row, which does
// not depend on the thread count: the same bits for 1, 2 and 3 threads.
TEST(ScaleSequentialImpacts, SameStateForOneTwoAndThreeThreads) {
  const auto run = [](int threads) {
    HardDiskGas gas = hardDiskGas(60, 0.45, 0.9, 1.0 / 60.0, 3.0, 5);
    gas.scene.solver.scaleSequentialImpacts = true;
    gas.scene.solver.threads = threads;
    gas.scene.solver.scaleParallelFrom = 0;
    World world(gas.scene);
    long long replayed = 0;
    for (int k = 0; k < 120; ++k) {
      world.step();
      replayed += world.stats().sequentialGroups;
    }
    return std::pair{stateHash(world), replayed};
  };
  const auto one = run(1);
  EXPECT_GT(one.second, 0);
  EXPECT_EQ(run(2), one);
  EXPECT_EQ(run(3), one);
}

}  // namespace
}  // namespace particles::test
