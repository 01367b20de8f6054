// The large-scene path's soft step (SolverSettings::scaleSubsteps;
// docs/scale.md, "The soft step"): gravity substep by substep as its closed
// form says, momentum kept by every impulse (no support sweep, no overlap
// removal), the Coulomb bound, the bounce of an isolated impact, the same
// bits for any thread count, and a pile that comes to rest.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "large_path_scene.h"
#include "particles/pile/pile_scene.h"
#include "particles/state_hash.h"
#include "particles/world.h"
#include "pile_rest.h"

namespace particles {
namespace {

Vec2 momentum(const World& world, const SceneDef& scene) {
  Vec2 p = Vec2::Zero();
  const std::vector<BallState> balls = world.balls();
  for (std::size_t i = 0; i < balls.size(); ++i) p += scene.balls[i].mass * balls[i].velocity;
  return p;
}

double kineticEnergy(const World& world, const SceneDef& scene) {
  double e = 0.0;
  const std::vector<BallState> balls = world.balls();
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const BallDef& d = scene.balls[i];
    e += 0.5 * d.mass * balls[i].velocity.squaredNorm() +
         0.5 * d.resolvedInertia() * balls[i].angularVelocity * balls[i].angularVelocity;
  }
  return e;
}

// Free fall, k substeps a step: the velocity after substep u of a step is
// v + u g h (h = dt / k), and the step moves the ball by h times the sum of
// those, v dt + g dt^2 (k + 1) / (2 k). After n steps from rest at y0:
//   v_n = n g dt,  y_n = y0 + g dt^2 (n (n - 1) / 2 + n (k + 1) / (2 k)),
// which tends to the exact parabola y0 + g (n dt)^2 / 2 as k grows, the gap
// being g dt^2 n / (2 k). Worked out by hand, not from the program.
TEST(SoftStep, FreeFallIsTheClosedFormOfItsSubsteps) {
  const double dt = 1.0 / 60.0, g = 10.0, y0 = 50.0;
  const int n = 30;
  for (int k : {1, 2, 4, 8}) {
    SceneDef scene = test::largePathScene(dt, g, {-100.0, -100.0}, {100.0, 100.0});
    scene.solver.scaleSubsteps = k;
    BallDef b;
    b.position = {0.0, y0};
    b.radius = 0.5;
    scene.balls.push_back(b);
    World world(scene);
    ASSERT_TRUE(world.plan().scale);
    world.run(n);
    const BallState s = world.balls()[0];
    const double expectY = y0 - g * dt * dt * (n * (n - 1) / 2.0 + n * (k + 1) / (2.0 * k));
    EXPECT_NEAR(s.velocity.y(), -n * g * dt, 1e-12) << "substeps " << k;
    EXPECT_EQ(s.velocity.x(), 0.0);
    EXPECT_NEAR(s.position.y(), expectY, 1e-11) << "substeps " << k;
    // The gap to the exact parabola, g dt^2 n / (2 k), halves with k.
    const double exact = y0 - 0.5 * g * (n * dt) * (n * dt);
    EXPECT_NEAR(exact - s.position.y(), g * dt * dt * n / (2.0 * k), 1e-11) << "substeps " << k;
  }
}

// Two balls, no gravity, on the large path: an oblique impact with spins.
SceneDef twoBalls(double offset) {
  SceneDef scene = test::largePathScene(1.0 / 60.0, 0.0, {-100.0, -100.0}, {100.0, 100.0});
  scene.walls.clear();
  scene.contact = {0.5, 0.5};  // e, mu
  scene.solver.scaleSubsteps = 4;
  BallDef a, b;
  a.position = {0.0, 0.0};
  a.velocity = {3.0, 0.0};
  a.angularVelocity = 4.0;
  a.radius = 0.5;
  a.mass = 1.0;
  b.position = {1.02, offset};
  b.velocity = {-1.0, 0.0};
  b.angularVelocity = -2.0;
  b.radius = 0.5;
  b.mass = 2.0;
  scene.balls = {a, b};
  return scene;
}

// Every impulse of the soft step is exchanged between the two balls of a row:
// the momentum stays to rounding through the impact; the springs and the
// bounce (e < 1) take energy out, never put it in; every row's impulses keep
// the Coulomb bound, step by step.
TEST(SoftStep, AnIsolatedImpactKeepsMomentumAndLosesEnergy) {
  for (double offset : {0.0, 0.3, 0.7}) {
    const SceneDef scene = twoBalls(offset);
    World world(scene);
    world.recordImpacts(true);
    ASSERT_TRUE(world.plan().scale);
    const Vec2 p0 = momentum(world, scene);
    const double e0 = kineticEnergy(world, scene);
    int pushed = 0;
    for (int step = 0; step < 30; ++step) {
      world.step();
      for (const ImpactEvent& ev : world.impacts()) {
        EXPECT_GE(ev.normalImpulse, 0.0);
        EXPECT_LE(std::fabs(ev.tangentImpulse), ev.frictionBound * (1.0 + 1e-12) + 1e-15);
        ++pushed;
      }
      EXPECT_NEAR((momentum(world, scene) - p0).norm(), 0.0, 1e-12) << "offset " << offset;
      EXPECT_LE(kineticEnergy(world, scene), e0 * (1.0 + 1e-12)) << "offset " << offset;
    }
    EXPECT_GT(pushed, 0) << "offset " << offset;
    EXPECT_LT(kineticEnergy(world, scene), e0) << "offset " << offset;
  }
}

// Head on (no spin, no friction): the normal relative velocity after the
// step of the impact is -e times the approach, the bounce the restitution
// pass asks for, and the balls part at that speed: the relative velocity
// along the line of centres goes from -4 m/s to +2 m/s for e = 1/2.
TEST(SoftStep, AHeadOnImpactBouncesWithItsRestitution) {
  SceneDef scene = twoBalls(0.0);
  scene.contact = {0.5, 0.0};
  for (BallDef& b : scene.balls) b.angularVelocity = 0.0;
  World world(scene);
  const double approach = -4.0;  // m/s, b's velocity less a's along x
  world.run(30);
  const std::vector<BallState> s = world.balls();
  EXPECT_NEAR(s[1].velocity.x() - s[0].velocity.x(), -0.5 * approach, 1e-12);
  EXPECT_GT(s[1].position.x() - s[0].position.x(), 1.0);  // parted
}

// bandRows >= 0: bands of that height at this size (the benchmark's
// 100,000 pile has bands of 2 grid rows).
std::uint64_t pileHash(int threads, int steps, bool poly, int substeps, int bandRows = -1,
                       bool wavefront = true) {
  pile::PileParams p;
  p.count = 2500;
  p.polydisperse = poly;
  p.threads = threads;
  SceneDef scene = pile::makePile(p);
  scene.solver.scaleParallelFrom = 0;  // share the step among the threads at this size too
  scene.solver.scaleSubsteps = substeps;
  if (bandRows >= 0) {
    scene.solver.scaleBandRows = bandRows;
    scene.solver.scaleBandsFrom = 0;
  }
  scene.solver.scaleWavefront = wavefront;
  World world(scene);
  EXPECT_TRUE(world.plan().scale);
  world.run(steps);
  return stateHash(world);
}

// Three threads on the two cores of the test machine wait for each other
// at every substep's barriers (and, in bands, at every band: 154 s under
// load with bands against 9 s idle), so they run on the monodisperse pile
// only, in whole strips; the soft step takes the rows in the same order as
// the rigid one, whose bands ScaleDeterminism.* cover.
TEST(SoftStep, SameHashWithOneTwoAndThreeThreads) {
  for (bool poly : {false, true}) {
    const std::uint64_t one = pileHash(1, 120, poly, 4);
    EXPECT_EQ(pileHash(2, 120, poly, 4), one) << "poly " << poly;
    if (!poly) {
      EXPECT_EQ(pileHash(3, 120, poly, 4), one);
    }
    EXPECT_NE(pileHash(1, 120, poly, 0), one) << "poly " << poly;  // the setting is taken
  }
}

// In bands, each substep's passes over rows and balls run as a wavefront
// (docs/scale.md, "The soft step's wavefront"): the same bits as the same
// passes one after another, with one thread or two (whose ball passes wait
// for each other's rows where their strips meet, with no barrier).
TEST(SoftStep, WavefrontInBandsGivesTheBitsOfWholePasses) {
  const std::uint64_t whole = pileHash(1, 120, false, 4, 2, false);
  EXPECT_EQ(pileHash(1, 120, false, 4, 2, true), whole);
  EXPECT_EQ(pileHash(2, 120, false, 4, 2, true), whole);
  EXPECT_EQ(pileHash(2, 120, false, 4, 2, false), whole);
  EXPECT_NE(pileHash(1, 120, false, 4, 0), whole);  // bands change the order: the setting is taken
}

// The benchmark's pile of `count` disks, with the soft step of 4 substeps.
SceneDef softPile(int count) {
  pile::PileParams p;
  p.count = count;
  SceneDef scene = pile::makePile(p);
  scene.solver.scaleSubsteps = 4;
  return scene;
}

// Gravity and the walls are the only outside impulses: over a step the
// pile's momentum changes by M g dt plus what the walls gave (the impact
// events' impulses; a wall row gives the ball -(lambdaN n + lambdaT tau)),
// while it lands and once it rests. The rigid step's support sweep does not
// keep this (it lifts balls with no reaction). Steps in which a ball moves
// faster than the rows' margin a step (0.2 of its radius) are left out:
// the wall guard may give such a ball an impact of its own, which is not an
// event.
TEST(SoftStep, ThePilesMomentumChangesByGravityAndTheWallsAlone) {
  const SceneDef scene = softPile(2000);
  World world(scene);
  ASSERT_TRUE(world.plan().scale);
  double mass = 0.0;
  for (const BallDef& b : scene.balls) mass += b.mass;
  const Vec2 weight = mass * scene.dt * scene.gravity;  // N s, gravity's impulse a step
  const double guardSpeed = 0.2 * pile::kRadius / scene.dt;
  const auto fastest = [&] {
    double v = 0.0;
    for (const BallState& b : world.balls()) v = std::max(v, b.velocity.norm());
    return v;
  };
  world.recordImpacts(true);
  int checked = 0;
  for (int step = 1; step <= 600; ++step) {
    const Vec2 before = momentum(world, scene);
    const bool slow = fastest() + std::fabs(weight.y()) / mass < guardSpeed;
    world.step();
    if (!slow || fastest() >= guardSpeed) continue;
    Vec2 walls = Vec2::Zero();
    for (const ImpactEvent& ev : world.impacts())
      if (ev.wall) walls -= ev.normalImpulse * ev.normal + ev.tangentImpulse * perpLeft(ev.normal);
    const Vec2 change = momentum(world, scene) - before;
    EXPECT_NEAR((change - weight - walls).norm(), 0.0, 1e-9 * weight.norm()) << "step " << step;
    ++checked;
  }
  EXPECT_GT(checked, 300);  // the pile is slow from about step 150
}

// The 2,000 pile comes to rest (the criterion: kinetic energy at
// most the whole mass at 1 cm/s) and stays there over the last 100 of 600
// steps.
TEST(SoftStep, APileComesToRest) {
  const SceneDef scene = softPile(2000);
  World world(scene);
  const pile::RestRun run = pile::runForRest(world, scene, 600, 100);
  EXPECT_TRUE(run.atRest) << "kinetic energy at the end " << run.finalEnergy << " J";
}

}  // namespace
}  // namespace particles
