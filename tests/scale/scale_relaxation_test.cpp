// Over-relaxation of the large-scene path's normal impulses
// (SolverSettings::scaleOverRelaxation, docs/scale.md, "Over-relaxation"),
// judged by what it is for: a pile that carries its weight to the floor
// comes to rest and keeps its disks apart.
//
// The 2,000-disk pile of issue 5 (radius 0.5 m, mu = 0.5, e = 0.5, dropped
// from a loose grid into a box) with the default settings, over the issue's
// 600 steps. At rest means the criterion (pile_metrics.h): the
// kinetic energy stays at or below that of the whole mass moving at 1 cm/s,
// here over the last 50 steps at least.
//
// Whether one given seed is at rest by then is chaos: a change at the
// rounding level anywhere in the step gives another pile, and a settled pile
// sometimes has an arch give way a hundred steps later (docs/scale.md,
// "Coming to rest is counted over seeds"). So the test counts seeds. With
// the default over-relaxation 6 of these 8 seeds were at rest (34 of 36 over
// seeds 20261201-36), 8 of 8 since the settle iteration
// (SolverSettings::scaleSettleIteration); with plain Gauss-Seidel (w = 1)
// none was (7 never at rest, one from step 563). At least 5 of 8 separates
// the two: for a solver that rests 90 % of its seeds, requiring 5 or more of
// 8 fails about once in 200 changes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <vector>

#include "particles/pile/pile_metrics.h"
#include "particles/pile/pile_scene.h"
#include "particles/state_hash.h"
#include "particles/world.h"
#include "pile_rest.h"

namespace particles::pile {
namespace {

constexpr long long kSteps = 600;     // 10 s of 1/60 s
constexpr long long kAtRestFor = 50;  // steps
constexpr int kSeeds = 8;
constexpr int kAtRestAtLeast = 5;

TEST(SettledPile, MostSeedsComeToRestWithTheirDisksApart) {
  int atRest = 0;
  for (int k = 0; k < kSeeds; ++k) {
    PileParams p;
    p.count = 2000;
    p.seed = 20261201u + static_cast<std::uint64_t>(k);
    const SceneDef scene = makePile(p);
    ASSERT_GT(scene.solver.scaleOverRelaxation, 1.0);
    World world(scene);
    ASSERT_TRUE(world.plan().scale);
    const RestRun run = runForRest(world, scene, kSteps, kAtRestFor);
    atRest += run.atRest ? 1 : 0;
    // Overlap, as a fraction of the smaller radius: a pile at rest keeps its
    // disks apart to 0.1 %; one where an arch is still giving way within the
    // issue's bound for a pile at rest, 5 %.
    const OverlapFigures overlap = measureOverlap(world.balls(), scene.balls);
    // A pile, not a gas: at least one pair touching to 1e-9 for every two
    // disks (the 10,000-disk piles at rest have 1.3-1.4 a disk; seed
    // 20261201 here 0.95 since the restitution pass updates the friction,
    // more than 1 before; a gas has next to none).
    EXPECT_GT(overlap.touchingPairs, p.count / 2) << "seed " << p.seed;
    EXPECT_LT(overlap.max, run.atRest ? 1e-3 : 0.05) << "seed " << p.seed;
    std::printf("seed %llu: %s, kinetic energy at the end %.3g J, max overlap %.3g %%\n",
                static_cast<unsigned long long>(p.seed), run.atRest ? "at rest" : "not at rest",
                run.finalEnergy, 100.0 * overlap.max);
  }
  EXPECT_GE(atRest, kAtRestAtLeast) << "of " << kSeeds << " seeds";
}

// The total energy of a pile: kinetic plus potential (m g y, y up, g = 10).
double totalEnergy(const World& world, const SceneDef& scene) {
  const std::vector<BallState> balls = world.balls();
  double potential = 0.0;
  for (std::size_t i = 0; i < balls.size(); ++i)
    potential += scene.balls[i].mass * -kGravity * balls[i].position.y();
  return kineticEnergy(balls, scene.balls) + potential;
}

// With few iterations, over-relaxation erupts a deep pile (docs/scale.md,
// "Few iterations and over-relaxation"): the overshoot of the over-relaxed
// updates that the last plain iteration cannot take back is warm-started
// into the next step. So below SolverSettings::scaleOverRelaxationFrom the
// iterations are plain. Judged by the law it broke: once the 5,000 pile has
// landed (step 300) nothing in it may gain energy, every contact being
// dissipative (e = 0.5, mu = 0.5), so its kinetic plus potential energy
// may only fall. The allowance is the whole pile lifted by 1 % of a radius,
// the order of what the overlap removal may put back (it moves balls, not
// velocities). With 2 iterations over-relaxed (scaleOverRelaxationFrom = 1,
// the code before the guard) the energy rose by 1.4 MJ, 1.3 times the
// pile's energy at step 300, by step 900 (and the 10,000 pile ended in a
// StepError at step 735); plain, it fell all along (by at least 104 J).
TEST(OverRelaxation, FewIterationsDoNotEruptALandedPile) {
  PileParams p;
  p.count = 5000;
  SceneDef scene = makePile(p);
  scene.solver.scaleVelocityIterations = 2;
  ASSERT_LT(scene.solver.scaleVelocityIterations, scene.solver.scaleOverRelaxationFrom);
  World world(scene);
  ASSERT_TRUE(world.plan().scale);
  world.run(300);
  const double landed = totalEnergy(world, scene);
  double mass = 0.0;
  for (const BallDef& b : scene.balls) mass += b.mass;
  const double allowance = mass * -kGravity * 0.01 * kRadius;
  double highest = -std::numeric_limits<double>::infinity();
  for (int step = 300; step < 900; ++step) {
    world.step();
    highest = std::max(highest, totalEnergy(world, scene));
  }
  EXPECT_LE(highest, landed + allowance) << "energy at step 300: " << landed << " J";
}

// Below scaleOverRelaxationFrom iterations the step is that of plain
// Gauss-Seidel to the bit, whatever scaleOverRelaxation says; from it on,
// over-relaxation changes the step.
TEST(OverRelaxation, OnlyFromItsIterationCount) {
  const auto finalHash = [](int iterations, double relaxation, int from) {
    PileParams p;
    p.count = 2000;
    SceneDef scene = makePile(p);
    scene.solver.scaleVelocityIterations = iterations;
    scene.solver.scaleOverRelaxation = relaxation;
    scene.solver.scaleOverRelaxationFrom = from;
    World world(scene);
    world.run(200);
    return stateHash(world);
  };
  const int from = SolverSettings{}.scaleOverRelaxationFrom;
  ASSERT_GT(from, 2);
  EXPECT_EQ(finalHash(from - 1, 1.8, from), finalHash(from - 1, 1.0, from));
  EXPECT_NE(finalHash(from - 1, 1.8, 1), finalHash(from - 1, 1.0, 1));
  EXPECT_NE(finalHash(from, 1.8, from), finalHash(from, 1.0, from));
}

}  // namespace
}  // namespace particles::pile
