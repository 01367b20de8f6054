// checkBox2DRange: nothing on an ordinary scene, and exactly the intended
// limit on scenes built to break one.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>

#include "particles/reference/box2d_range.h"
#include "reference_test_support.h"

namespace particles::reference {
namespace {

using testing::ball;

// Two half-metre balls in a 4 m box under gravity, 5 m/s, friction, one
// no-slip ball: well inside Box2D's range.
SceneDef ordinary() {
  SceneDef s;
  s.dt = 1e-3;
  s.duration = 2.0;
  s.gravity = {0.0, -9.81};
  s.contact = {0.8, 0.3};
  s.walls = boxWalls({-2.0, -2.0}, {2.0, 2.0});
  BallDef a = ball({-1.0, 0.0}, {5.0, 1.0});
  a.angularVelocity = 10.0;
  BallDef b = ball({1.0, 0.0}, {-3.0, 0.0}, 0.3, 0.5);
  b.friction = kNoSlip;
  s.balls = {a, b};
  ForceDef pull;
  pull.ball = 0;
  pull.target = {0.0, 1.0};
  pull.stiffness = 10.0;
  s.forces = {pull};
  return s;
}

std::set<RangeCode> codes(const SceneDef& scene, const Box2DSettings& settings) {
  std::set<RangeCode> out;
  for (const RangeIssue& issue : checkBox2DRange(scene, settings)) {
    EXPECT_FALSE(issue.message.empty());
    out.insert(issue.code);
  }
  return out;
}

std::set<RangeCode> codes(const SceneDef& scene) {
  return codes(scene, Box2DSettings::forScene(scene));
}

using Codes = std::set<RangeCode>;

TEST(Box2DRange, OrdinarySceneIsInRange) {
  const SceneDef s = ordinary();
  for (const RangeIssue& issue : checkBox2DRange(s, Box2DSettings::forScene(s)))
    ADD_FAILURE() << rangeCodeName(issue.code) << ": " << issue.message;
}

TEST(Box2DRange, FloatRange) {
  SceneDef s = ordinary();
  s.balls[1].velocity.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(codes(s), Codes{RangeCode::FloatRange});
  const std::vector<RangeIssue> issues = checkBox2DRange(s, Box2DSettings::forScene(s));
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].index, 1);
}

TEST(Box2DRange, MaxTranslation) {
  SceneDef s = ordinary();
  s.contact.friction = 0.0;  // else the spin friction could give is flagged too
  s.balls[1].friction.reset();
  s.balls[0].velocity = {2500.0, 0.0};  // 2.5 m per 1 ms step > b2_maxTranslation
  EXPECT_EQ(codes(s), Codes{RangeCode::MaxTranslation});

  // Reached only through a constant force: 1e6 N on 1 kg for 2 s.
  SceneDef pushed = ordinary();
  pushed.contact.friction = 0.0;
  pushed.balls[1].friction.reset();
  ForceDef push;
  push.type = ForceType::Constant;
  push.ball = 0;
  push.force = {1e6, 0.0};
  pushed.forces.push_back(push);
  EXPECT_EQ(codes(pushed), Codes{RangeCode::MaxTranslation});
}

TEST(Box2DRange, MaxRotation) {
  SceneDef s = ordinary();
  s.balls[0].angularVelocity = 2000.0;  // 2 rad per step > b2_maxRotation (pi/2)
  EXPECT_EQ(codes(s), Codes{RangeCode::MaxRotation});
}

TEST(Box2DRange, RadiusRangeAndLinearSlop) {
  SceneDef big = ordinary();
  big.balls[0].radius = 12.0;
  EXPECT_EQ(codes(big), Codes{RangeCode::RadiusRange});
  SceneDef small = ordinary();
  small.balls[1].radius = 0.07;  // under 0.1 m, but still 14 slops
  EXPECT_EQ(codes(small), Codes{RangeCode::RadiusRange});
  SceneDef tiny = ordinary();
  tiny.balls[1].radius = 0.04;  // 8 b2_linearSlop
  EXPECT_EQ(codes(tiny), (Codes{RangeCode::RadiusRange, RangeCode::LinearSlop}));
}

TEST(Box2DRange, WallLength) {
  SceneDef s = ordinary();
  s.walls = boxWalls({-30.0, -2.0}, {30.0, 2.0});
  EXPECT_EQ(codes(s), Codes{RangeCode::WallLength});
}

TEST(Box2DRange, PositionPrecision) {
  SceneDef s = ordinary();
  const Vec2 far(1e5, 0.0);  // float spacing there: 7.8e-3 m
  for (BallDef& b : s.balls) b.position += far;
  for (WallDef& w : s.walls) {
    w.a += far;
    w.b += far;
  }
  for (ForceDef& f : s.forces) f.target += far;
  EXPECT_EQ(codes(s), Codes{RangeCode::PositionPrecision});
}

TEST(Box2DRange, MassRatio) {
  SceneDef s = ordinary();
  s.balls[1].mass = 1e7;
  EXPECT_EQ(codes(s), Codes{RangeCode::MassRatio});
}

TEST(Box2DRange, NoSlipMixing) {
  SceneDef s = ordinary();
  s.walls[0].friction = 1e-9;  // sqrt(1e12 * 1e-9) = 32
  EXPECT_EQ(codes(s), Codes{RangeCode::NoSlipMixing});

  SceneDef both = ordinary();
  both.balls[0].friction = kNoSlip;
  Box2DSettings weak = Box2DSettings::forScene(both);
  weak.noSlipFriction = 10.0;
  EXPECT_EQ(codes(both, weak), Codes{RangeCode::NoSlipMixing});
  EXPECT_TRUE(codes(both).empty());

  SceneDef grippyWall = ordinary();
  grippyWall.balls[1].friction = 1e-9;
  grippyWall.walls[3].friction = kNoSlip;
  EXPECT_EQ(codes(grippyWall), Codes{RangeCode::NoSlipMixing});

  SceneDef smooth = ordinary();  // a no-slip ball among smooth bodies never grips
  smooth.contact.friction = 0.0;
  EXPECT_TRUE(codes(smooth).empty());
}

TEST(Box2DRange, SolverIterations) {
  const SceneDef s = ordinary();
  Box2DSettings settings = Box2DSettings::forScene(s);
  settings.velocityIterations = 1;
  EXPECT_EQ(codes(s, settings), Codes{RangeCode::VelocityIterations});
  settings.velocityIterations = 2;
  settings.positionIterations = 0;
  EXPECT_EQ(codes(s, settings), Codes{RangeCode::PositionIterations});
}

TEST(Box2DRange, CodeNamesAreDistinct) {
  std::set<std::string> names;
  for (int c = 0; c <= static_cast<int>(RangeCode::PositionIterations); ++c)
    names.insert(rangeCodeName(static_cast<RangeCode>(c)));
  EXPECT_EQ(names.size(), static_cast<std::size_t>(RangeCode::PositionIterations) + 1);
}

}  // namespace
}  // namespace particles::reference
