// Pair finding. The brute-force finder is the oracle: first it is checked
// against the definition of touching (|x_b - x_a| <= r_a + r_b, normal from a
// to b, overlap r_a + r_b - |d|), then the grid must return exactly the same
// pairs, in the same order, with bit-identical normals and overlaps, and the
// World's results must not depend on which finder it uses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include "particles/broad_phase.h"
#include "particles/world.h"
#include "physics_test_support.h"

namespace {

using namespace physics_test;
using particles::BallPair;

struct Balls {
  std::string kind;
  std::vector<Vec2> position;
  std::vector<double> radius;
};

enum class Layout { Uniform, Polydisperse, Clustered, Sparse };

const char* name(Layout l) {
  switch (l) {
    case Layout::Uniform:
      return "uniform radii";
    case Layout::Polydisperse:
      return "polydisperse";
    case Layout::Clustered:
      return "clustered";
    case Layout::Sparse:
      return "sparse";
  }
  return "?";
}

// n balls; the box is sized for an area fraction `fill` of the disks (fill > 1
// means heavy overlap), and Sparse spreads them over a box 1000 times wider.
Balls makeBalls(Random& rand, Layout layout, int n, double fill) {
  Balls b;
  b.kind =
      std::string(name(layout)) + ", n = " + std::to_string(n) + ", fill = " + std::to_string(fill);
  double area = 0.0;
  for (int i = 0; i < n; ++i) {
    const double r = layout == Layout::Polydisperse ? rand.logUniform(0.01, 1.0) : 0.5;
    b.radius.push_back(r);
    area += std::numbers::pi * r * r;
  }
  double side = std::sqrt(area / fill);
  if (layout == Layout::Sparse) side *= 1000.0;
  if (layout == Layout::Clustered) {
    const int clusters = 1 + n / 50;
    std::vector<Vec2> centre;
    for (int c = 0; c < clusters; ++c)
      centre.emplace_back(rand.uniform(0.0, 10.0 * side), rand.uniform(0.0, 10.0 * side));
    const double spread = std::sqrt(static_cast<double>(n) / clusters / fill) * 0.6;
    for (int i = 0; i < n; ++i) {
      const Vec2& c = centre[static_cast<std::size_t>(rand.bits() % clusters)];
      b.position.emplace_back(c.x() + spread * rand.uniform(-1.0, 1.0),
                              c.y() + spread * rand.uniform(-1.0, 1.0));
    }
  } else {
    for (int i = 0; i < n; ++i)
      b.position.emplace_back(rand.uniform(-side / 2, side / 2), rand.uniform(-side / 2, side / 2));
  }
  return b;
}

// Same pairs, same order, bit-identical geometry.
void expectSamePairs(const std::vector<BallPair>& want, const std::vector<BallPair>& got,
                     const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < want.size(); ++i) {
    ASSERT_EQ(got[i].a, want[i].a) << what << ", pair " << i;
    ASSERT_EQ(got[i].b, want[i].b) << what << ", pair " << i;
    ASSERT_EQ(got[i].normal, want[i].normal) << what << ", pair " << i;
    ASSERT_EQ(got[i].overlap, want[i].overlap) << what << ", pair " << i;
  }
}

TEST(BroadPhase, BruteForceFindsExactlyTheTouchingPairs) {
  Random rand(0x5eed'0012);
  for (Layout layout : {Layout::Uniform, Layout::Polydisperse, Layout::Clustered}) {
    for (int n : {2, 10, 300}) {
      const Balls balls = makeBalls(rand, layout, n, 0.6);
      std::vector<BallPair> pairs;
      particles::findPairsBruteForce(balls.position, balls.radius, pairs);
      std::size_t k = 0;
      for (int a = 0; a < n; ++a) {
        for (int b = a + 1; b < n; ++b) {
          const Vec2 d = balls.position[b] - balls.position[a];
          const double reach = balls.radius[a] + balls.radius[b];
          const bool listed = k < pairs.size() && pairs[k].a == a && pairs[k].b == b;
          // Clear cases only: the slop of 1e-9 (relative) lies between.
          if (d.norm() < reach * (1.0 - 1e-12)) {
            ASSERT_TRUE(listed) << balls.kind << ": touching pair (" << a << ", " << b
                                << ") missing";
          } else if (d.norm() > reach * (1.0 + 2e-9)) {
            ASSERT_FALSE(listed) << balls.kind << ": apart pair (" << a << ", " << b << ") listed";
          }
          if (!listed) continue;
          const BallPair& p = pairs[k++];
          EXPECT_NEAR(p.normal.norm(), 1.0, 4 * kEps);
          EXPECT_NEAR((p.normal - d / d.norm()).norm(), 0.0, 4 * kEps);
          EXPECT_NEAR(p.overlap, reach - d.norm(), 4 * kEps * reach);
        }
      }
      EXPECT_EQ(k, pairs.size()) << balls.kind << ": pairs out of (a, b) order";
    }
  }
}

TEST(BroadPhase, GridMatchesBruteForceOnRandomScenes) {
  Random rand(0x5eed'0013);
  particles::BroadPhase grid;  // reused across scenes, as the World does
  std::size_t scenes = 0, pairsSeen = 0;
  for (Layout layout : {Layout::Uniform, Layout::Polydisperse, Layout::Clustered, Layout::Sparse}) {
    for (int n : {2, 3, 7, 48, 200, 1000, 2000}) {
      for (double fill : {0.05, 0.5, 1.5}) {
        const Balls balls = makeBalls(rand, layout, n, fill);
        std::vector<BallPair> want, got;
        particles::findPairsBruteForce(balls.position, balls.radius, want);
        grid.findPairs(balls.position, balls.radius, got);
        expectSamePairs(want, got, balls.kind);
        ++scenes;
        pairsSeen += want.size();
      }
    }
  }
  std::printf("[ measured ] grid vs brute force: %zu scenes, %zu pairs, all identical\n", scenes,
              pairsSeen);
  EXPECT_GT(pairsSeen, 10000u) << "scenes too sparse to test anything";
}

// Degenerate layouts: every centre at one point (no normal: the fixed (1, 0)),
// all on one line (a grid one cell high), a square lattice of exactly
// touching balls (every neighbour on a cell boundary).
TEST(BroadPhase, GridMatchesBruteForceOnDegenerateScenes) {
  particles::BroadPhase grid;
  std::vector<Balls> scenes;
  {
    Balls b{"coincident centres", {}, {}};
    for (int i = 0; i < 20; ++i) {
      b.position.emplace_back(1.5, -2.5);
      b.radius.push_back(0.1 + 0.01 * i);
    }
    scenes.push_back(b);
  }
  {
    Balls b{"collinear", {}, {}};
    for (int i = 0; i < 500; ++i) {
      b.position.emplace_back(0.9 * i, 3.0);
      b.radius.push_back(0.5);
    }
    scenes.push_back(b);
  }
  {
    Balls b{"touching lattice", {}, {}};
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 40; ++j) {
        b.position.emplace_back(1.0 * i, 1.0 * j);
        b.radius.push_back(0.5);
      }
    scenes.push_back(b);
  }
  for (const Balls& balls : scenes) {
    std::vector<BallPair> want, got;
    particles::findPairsBruteForce(balls.position, balls.radius, want);
    grid.findPairs(balls.position, balls.radius, got);
    expectSamePairs(want, got, balls.kind);
    EXPECT_FALSE(want.empty()) << balls.kind;
  }
}

// Pairs accepted within the touching slop, |d| in (r_a + r_b,
// (r_a + r_b)(1 + 1e-9)], can be farther apart than one grid cell (cells are
// 2 r_max wide). Balls 1 and 2 below (radius 0.5, cell 1.0, grid origin at
// ball 0) are 1 + 4e-10 apart, so brute force lists them; ball 1 sits just
// below the boundary of cell 0, ball 2 just above that of cell 2, so the grid
// never compares them.
TEST(BroadPhase, GridFindsPairsWithinTheTouchSlopAcrossCellBoundaries) {
  const std::vector<Vec2> position = {Vec2(0.0, 0.0), Vec2(1.0 - 1e-10, 0.0),
                                      Vec2(2.0 + 3e-10, 0.0)};
  const std::vector<double> radius = {0.5, 0.5, 0.5};
  std::vector<BallPair> want, got;
  particles::findPairsBruteForce(position, radius, want);
  particles::BroadPhase grid;
  grid.findPairs(position, radius, got);
  ASSERT_EQ(want.size(), 2u) << "brute force: (0, 1) overlapping, (1, 2) within the slop";
  expectSamePairs(want, got, "pair within the slop across two cell boundaries");
}

// A World with the grid from the first ball (threshold 0) and one that never
// uses it must evolve bit for bit alike.
particles::SceneDef pile(int n) {
  particles::SceneDef scene;
  scene.gravity = Vec2(0.0, -9.81);
  scene.contact = particles::ContactMaterial{0.4, 0.5};
  scene.walls = particles::boxWalls(Vec2(0.0, 0.0), Vec2(20.0, 40.0));
  Random rand(0x5eed'0014);
  for (int i = 0; i < n; ++i) {
    particles::BallDef b;
    b.radius = rand.uniform(0.2, 0.5);
    b.mass = b.radius * b.radius * 4.0;
    b.position = Vec2(0.6 + 1.1 * (i % 17), 0.6 + 1.1 * (i / 17));
    b.velocity = Vec2(rand.uniform(-2.0, 2.0), rand.uniform(-2.0, 2.0));
    b.angularVelocity = rand.uniform(-5.0, 5.0);
    scene.balls.push_back(b);
  }
  return scene;
}

TEST(BroadPhase, WorldResultsDoNotDependOnThePairFinder) {
  particles::SceneDef withGrid = pile(300), bruteForce = pile(300);
  withGrid.solver.gridThreshold = 0;
  bruteForce.solver.gridThreshold = 1 << 30;
  particles::World a(withGrid), b(bruteForce);
  ASSERT_TRUE(a.plan().grid);
  ASSERT_FALSE(b.plan().grid);
  long long contacts = 0;
  for (int s = 0; s < 1500; ++s) {
    a.step();
    b.step();
    contacts += a.stats().contacts;
    ASSERT_EQ(a.stats().contacts, b.stats().contacts) << "step " << s + 1;
  }
  for (std::size_t i = 0; i < a.ballCount(); ++i) {
    const particles::BallState x = a.ball(i), y = b.ball(i);
    ASSERT_EQ(x.position, y.position) << "ball " << i;
    ASSERT_EQ(x.velocity, y.velocity) << "ball " << i;
    ASSERT_EQ(std::memcmp(&x.angle, &y.angle, sizeof(double)), 0) << "ball " << i;
    ASSERT_EQ(std::memcmp(&x.angularVelocity, &y.angularVelocity, sizeof(double)), 0)
        << "ball " << i;
  }
  std::printf("[ measured ] pile: %lld contacts over 1500 steps\n", contacts);
  EXPECT_GT(contacts, 50000) << "the pile must actually collide";
}

}  // namespace
