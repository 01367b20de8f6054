// The pile scene generator: box and grid sizes from the formulas,
// disk counts and properties, the seed's determinism, no initial overlap.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "particles/pile/pile_scene.h"

namespace particles::pile {
namespace {

TEST(PileScene, GeometryOfTenThousand) {
  const PileGeometry g = pileGeometry(10000);
  EXPECT_DOUBLE_EQ(g.width, 125.0);  // 1.25 sqrt(10000)
  EXPECT_EQ(g.columns, 104);         // floor(125 / 1.2)
  EXPECT_EQ(g.rows, 97);             // ceil(10000 / 104)
  EXPECT_NEAR(g.gridLeft, (125.0 - 104 * 1.2) / 2, 1e-12);
  // Settled pile: 10000 pi 0.25 m^2 at area fraction 0.82 over 125 m is
  // 76.62 m; filling 60 % of the box makes it 127.7 m, above the grid's top
  // (0.6 + 97 * 1.2 = 117 m) plus a spacing.
  const double settled = 10000 * std::numbers::pi * 0.25 / (0.82 * 125.0);
  EXPECT_NEAR(g.height, settled / 0.6, 1e-9);
  EXPECT_GT(g.height, 0.6 + 97 * 1.2 + 1.2);
}

TEST(PileScene, TinyPileStillHasABoxAroundItsGrid) {
  for (int n : {1, 2, 3, 7}) {
    const PileGeometry g = pileGeometry(n);
    EXPECT_GE(g.columns, 1);
    EXPECT_GE(g.width, g.columns * kSpacing);
    EXPECT_GE(g.height, g.gridBottom + g.rows * kSpacing + kSpacing);
  }
}

TEST(PileScene, CountsMaterialsAndBox) {
  PileParams p;
  p.count = 1234;
  const SceneDef s = makePile(p);
  const PileGeometry g = pileGeometry(1234);
  ASSERT_EQ(s.balls.size(), 1234u);
  ASSERT_EQ(s.walls.size(), 4u);
  EXPECT_EQ(s.walls[0].a, Vec2(0.0, 0.0));
  EXPECT_EQ(s.walls[1].b, Vec2(g.width, g.height));
  EXPECT_EQ(s.gravity, Vec2(0.0, -10.0));
  EXPECT_EQ(s.contact.restitution, 0.5);
  EXPECT_EQ(s.contact.friction, 0.5);
  EXPECT_DOUBLE_EQ(s.dt, 1.0 / 60.0);
  EXPECT_EQ(s.stepCount(), 600);
  for (const BallDef& b : s.balls) {
    EXPECT_EQ(b.radius, 0.5);
    EXPECT_DOUBLE_EQ(b.mass, std::numbers::pi * 0.25);  // density 1 kg/m^2
    EXPECT_EQ(b.velocity, Vec2::Zero());
    EXPECT_EQ(b.angularVelocity, 0.0);
  }
}

TEST(PileScene, PolydisperseRadiiSpanTheirRange) {
  PileParams p;
  p.count = 4000;
  p.polydisperse = true;
  const SceneDef s = makePile(p);
  double lo = 1.0, hi = 0.0, sum = 0.0;
  for (const BallDef& b : s.balls) {
    lo = std::min(lo, b.radius);
    hi = std::max(hi, b.radius);
    sum += b.radius;
    EXPECT_DOUBLE_EQ(b.mass, std::numbers::pi * b.radius * b.radius);
  }
  EXPECT_GE(lo, 0.4);
  EXPECT_LT(hi, 0.6);
  EXPECT_LT(lo, 0.41);
  EXPECT_GT(hi, 0.59);
  // Uniform on [0.4, 0.6]: mean 0.5, standard error 0.058 / sqrt(4000) = 0.0009.
  EXPECT_NEAR(sum / 4000, 0.5, 0.005);
}

TEST(PileScene, SameSeedSameSceneOtherSeedOtherScene) {
  PileParams p;
  p.count = 500;
  p.polydisperse = true;
  const SceneDef a = makePile(p), b = makePile(p);
  p.seed += 1;
  const SceneDef c = makePile(p);
  int differ = 0;
  for (std::size_t i = 0; i < a.balls.size(); ++i) {
    EXPECT_EQ(a.balls[i].position, b.balls[i].position);
    EXPECT_EQ(a.balls[i].radius, b.balls[i].radius);
    differ += a.balls[i].position != c.balls[i].position;
  }
  EXPECT_GT(differ, 490);
}

// Every disk inside the box and apart from every other, by brute force.
TEST(PileScene, NoInitialOverlap) {
  for (bool poly : {false, true}) {
    PileParams p;
    p.count = 1500;
    p.polydisperse = poly;
    const SceneDef s = makePile(p);
    const PileGeometry g = pileGeometry(p.count);
    for (std::size_t i = 0; i < s.balls.size(); ++i) {
      const BallDef& a = s.balls[i];
      EXPECT_GE(a.position.x() - a.radius, 0.0);
      EXPECT_LE(a.position.x() + a.radius, g.width);
      EXPECT_GT(a.position.y() - a.radius, 0.0);
      EXPECT_LT(a.position.y() + a.radius, g.height);
      for (std::size_t j = i + 1; j < s.balls.size(); ++j) {
        const BallDef& b = s.balls[j];
        ASSERT_GE((b.position - a.position).norm(), a.radius + b.radius) << i << " " << j;
      }
    }
  }
}

// The grid is loose: jitter moves a 0.5 m disk by at most 0.1 m per axis, so
// neighbours in a row are at least 1.0 m apart and on average 1.2 m.
TEST(PileScene, JitterStaysInsideTheCell) {
  PileParams p;
  p.count = 300;
  const SceneDef s = makePile(p);
  const PileGeometry g = pileGeometry(p.count);
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    const double cx = g.gridLeft + (static_cast<int>(i) % g.columns + 0.5) * kSpacing;
    const double cy = g.gridBottom + (static_cast<int>(i) / g.columns + 0.5) * kSpacing;
    EXPECT_LE(std::abs(s.balls[i].position.x() - cx), 0.1 + 1e-12);
    EXPECT_LE(std::abs(s.balls[i].position.y() - cy), 0.1 + 1e-12);
  }
}

}  // namespace
}  // namespace particles::pile
