// Over-relaxation of the large-scene path's normal impulses
// (SolverSettings::scaleOverRelaxation, docs/scale.md, "Over-relaxation"),
// judged by what it is for: a pile that carries its weight to the floor
// comes to rest and keeps its disks apart.
//
// The 2,000-disk pile of issue 5 (radius 0.5 m, mu = 0.5, e = 0.5, dropped
// from a loose grid into a box) with the default settings. At rest means the
// issue's criterion (pile_metrics.h): the kinetic energy stays at or below
// that of the whole mass moving at 1 cm/s. With plain Gauss-Seidel (w = 1)
// and the same 2 overlap-removal passes, neither seed below was at rest by
// step 600 (1 of 8 seeds was; docs/scale.md), and the largest overlaps were
// 0.42 and 0.48 % of the radius.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "particles/pile/pile_metrics.h"
#include "particles/pile/pile_scene.h"
#include "particles/world.h"

namespace particles::pile {
namespace {

constexpr long long kSteps = 400;  // 6.7 s of 1/60 s

class SettledPile : public testing::TestWithParam<std::uint64_t> {};

TEST_P(SettledPile, ComesToRestWithItsDisksApart) {
  PileParams p;
  p.count = 2000;
  p.seed = GetParam();
  const SceneDef scene = makePile(p);
  ASSERT_GT(scene.solver.scaleOverRelaxation, 1.0);
  World world(scene);
  ASSERT_TRUE(world.plan().scale);
  std::vector<double> energy;
  for (long long s = 0; s < kSteps; ++s) {
    world.step();
    energy.push_back(kineticEnergy(world.balls(), scene.balls));
  }
  const std::optional<long long> rest = restStep(energy, restEnergy(scene.balls));
  ASSERT_TRUE(rest.has_value()) << "kinetic energy at the end " << energy.back() << " J";
  // A pile at rest, not one that just passed through a slow moment: it has
  // stayed at rest over the last 50 steps at least.
  EXPECT_LE(*rest, kSteps - 50);
  const OverlapFigures overlap = measureOverlap(world.balls(), scene.balls);
  EXPECT_GT(overlap.touchingPairs, 2000);  // a pile, not a gas
  EXPECT_LT(overlap.max, 1e-3);            // of the smaller radius
}

INSTANTIATE_TEST_SUITE_P(Seeds, SettledPile, testing::Values(20261201u, 20261206u));

}  // namespace
}  // namespace particles::pile
