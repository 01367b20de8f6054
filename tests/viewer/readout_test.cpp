// The readout's numbers, from their definitions.
#include <gtest/gtest.h>

#include "particles/viewer/readout.h"

namespace particles::viewer {
namespace {

TEST(Readout, EnergiesAndMomentum) {
  SceneDef scene;
  scene.gravity = {0.0, -9.81};
  BallDef a, b;
  a.mass = 2.0;
  a.radius = 0.5;  // I = m r^2 / 2 = 0.25
  b.mass = 1.0;
  b.inertia = 0.1;
  scene.balls = {a, b};
  const std::vector<BallState> s = {{{0.0, 3.0}, {1.0, 2.0}, 0.0, 4.0},
                                    {{5.0, -1.0}, {-3.0, 0.0}, 0.0, -2.0}};
  const EnergyReadout e = measureEnergy(scene, s);
  EXPECT_DOUBLE_EQ(e.translational, 0.5 * 2.0 * 5.0 + 0.5 * 1.0 * 9.0);
  EXPECT_DOUBLE_EQ(e.rotational, 0.5 * 0.25 * 16.0 + 0.5 * 0.1 * 4.0);
  // m g y with y up: positive above y = 0, negative below.
  EXPECT_DOUBLE_EQ(e.potential, 2.0 * 9.81 * 3.0 - 1.0 * 9.81 * 1.0);
  EXPECT_EQ(e.momentum, Vec2(2.0 - 3.0, 4.0));
  EXPECT_DOUBLE_EQ(e.total(), e.translational + e.rotational + e.potential);
}

TEST(Readout, LargestDifferenceNamesTheBall) {
  const std::vector<BallState> engine = {{{0.0, 0.0}, {1.0, 0.0}, 0.0, 0.0},
                                         {{1.0, 1.0}, {0.0, 0.0}, 0.0, 0.0}};
  const std::vector<BallState> box2d = {{{0.0, 0.5}, {1.0, 0.0}, 0.0, 0.0},
                                        {{1.0, 1.1}, {0.0, -2.0}, 0.0, 0.0}};
  const Discrepancy d = largestDifference(engine, box2d);
  EXPECT_DOUBLE_EQ(d.position, 0.5);
  EXPECT_EQ(d.positionBall, 0);
  EXPECT_DOUBLE_EQ(d.velocity, 2.0);
  EXPECT_EQ(d.velocityBall, 1);
  EXPECT_EQ(largestDifference({}, {}).positionBall, -1);
}

TEST(Readout, LinesNameBothEnginesAndThePull) {
  SceneDef scene;
  BallDef ball;
  scene.balls = {ball};
  Session session(scene);
  session.hold(0, {1.0, 0.0});
  const std::vector<std::string> lines = readoutLines(session, ViewMode::Side);
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_NE(lines[0].find("mode side"), std::string::npos);
  EXPECT_EQ(lines[1].rfind("engine", 0), 0u);
  EXPECT_EQ(lines[2].rfind("Box2D", 0), 0u);
  EXPECT_NE(lines[3].find("max |dx|"), std::string::npos);
  EXPECT_NE(lines[4].find("k = 50 N/m"), std::string::npos);  // 50 N/m per kg, 1 kg
  EXPECT_NE(lines[4].find("|F| = k |M - O| = 50 N"), std::string::npos);
}

}  // namespace
}  // namespace particles::viewer
