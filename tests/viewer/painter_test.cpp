// What the painter asks a DebugDraw to draw, recorded without any renderer.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "particles/viewer/painter.h"
#include "particles/viewer/palette.h"

namespace particles::viewer {
namespace {

struct Call {
  std::string what;  // "circle", "solid", "segment", "point"
  Vec2 a{0.0, 0.0}, b{0.0, 0.0};
  double radius = 0.0, angle = 0.0;
  Color color;
};

class Recorder final : public DebugDraw {
 public:
  std::vector<Call> calls;
  void circle(const Vec2& c, double r, Color color) override {
    calls.push_back({"circle", c, c, r, 0.0, color});
  }
  void solidCircle(const Vec2& c, double r, double angle, Color fill, Color) override {
    calls.push_back({"solid", c, c, r, angle, fill});
  }
  void segment(const Vec2& a, const Vec2& b, Color color) override {
    calls.push_back({"segment", a, b, 0.0, 0.0, color});
  }
  void point(const Vec2& p, double size, Color color) override {
    calls.push_back({"point", p, p, size, 0.0, color});
  }
};

SceneDef twoBalls() {
  SceneDef scene;
  scene.walls = boxWalls({0.0, 0.0}, {4.0, 3.0});
  BallDef a, b;
  a.radius = 0.3;
  a.mass = 2.0;
  b.radius = 0.5;
  b.mass = 1.0;
  scene.balls = {a, b};
  return scene;
}

std::vector<BallState> states() {
  return {{{1.0, 1.0}, {0.0, 0.0}, 0.5, 0.0}, {{2.0, 1.0}, {0.0, 0.0}, -2.0, 0.0}};
}

TEST(Painter, EveryWallIsASegment) {
  Recorder r;
  drawWalls(r, twoBalls());
  ASSERT_EQ(r.calls.size(), 4u);
  EXPECT_EQ(r.calls[0].a, Vec2(0.0, 0.0));
  EXPECT_EQ(r.calls[0].b, Vec2(4.0, 0.0));
  for (const Call& c : r.calls) EXPECT_EQ(c.color, palette::kWall);
}

TEST(Painter, FilledBallsCarryTheirAngle) {
  Recorder r;
  drawBalls(r, twoBalls(), states(), {true, palette::kEngineBall, palette::kMarker});
  ASSERT_EQ(r.calls.size(), 2u);
  EXPECT_EQ(r.calls[0].what, "solid");
  EXPECT_EQ(r.calls[0].a, Vec2(1.0, 1.0));
  EXPECT_EQ(r.calls[0].radius, 0.3);
  EXPECT_EQ(r.calls[0].angle, 0.5);
  EXPECT_EQ(r.calls[1].angle, -2.0);
  EXPECT_EQ(r.calls[1].color, palette::kEngineBall);
}

TEST(Painter, GhostsAreAnOutlineAndARadiusAtTheAngle) {
  Recorder r;
  drawBalls(r, twoBalls(), states(), {false, palette::kBox2DBall, palette::kMarker});
  ASSERT_EQ(r.calls.size(), 4u);
  EXPECT_EQ(r.calls[0].what, "circle");
  EXPECT_EQ(r.calls[1].what, "segment");
  EXPECT_EQ(r.calls[1].a, Vec2(1.0, 1.0));
  EXPECT_LT((r.calls[1].b - Vec2(1.0 + 0.3 * std::cos(0.5), 1.0 + 0.3 * std::sin(0.5))).norm(),
            1e-15);
}

TEST(Painter, NonFiniteBallsAreSkipped) {
  Recorder r;
  std::vector<BallState> s = states();
  s[0].position.x() = std::nan("");
  drawBalls(r, twoBalls(), s, {true, palette::kEngineBall, palette::kMarker});
  EXPECT_EQ(r.calls.size(), 1u);
}

TEST(Painter, PullIsASegmentFromTheCentreToTheCursor) {
  Recorder r;
  drawPull(r, {1.0, 1.0}, {3.0, 2.5});
  ASSERT_GE(r.calls.size(), 1u);
  EXPECT_EQ(r.calls[0].what, "segment");
  EXPECT_EQ(r.calls[0].a, Vec2(1.0, 1.0));
  EXPECT_EQ(r.calls[0].b, Vec2(3.0, 2.5));
  EXPECT_EQ(r.calls[0].color, palette::kDrag);
}

TEST(Painter, ImpactShowsTheNormalAtTheContactAndOpposedImpulses) {
  // Ball 0 hits ball 1 along +x: P = lambda_n n goes +x into ball 1 and -x
  // into ball 0, both from the contact point x_0 + r_0 n.
  ImpactEvent e;
  e.a = 0;
  e.b = 1;
  e.normal = {1.0, 0.0};
  e.normalImpulse = 0.5;
  Recorder r;
  drawImpacts(r, twoBalls(), states(), {e});
  const Vec2 c(1.3, 1.0);
  ASSERT_EQ(r.calls.size(), 7u);  // normal + two arrows of three strokes
  EXPECT_EQ(r.calls[0].color, palette::kNormal);
  EXPECT_EQ(r.calls[0].a, c);
  EXPECT_LT((r.calls[0].b - (c + kNormalRadii * 0.3 * e.normal)).norm(), 1e-15);
  // Into ball 0 (mass 2): length 0.5 / 2 * 0.1 s = 0.025 m toward -x.
  EXPECT_EQ(r.calls[1].a, c);
  EXPECT_LT((r.calls[1].b - (c - Vec2(0.025, 0.0))).norm(), 1e-15);
  // Into ball 1 (mass 1): 0.05 m toward +x.
  EXPECT_EQ(r.calls[4].a, c);
  EXPECT_LT((r.calls[4].b - (c + Vec2(0.05, 0.0))).norm(), 1e-15);
}

TEST(Painter, WallImpactArrowPushesTheBallOffTheWall) {
  ImpactEvent e;
  e.a = 1;
  e.b = 0;  // the floor
  e.wall = true;
  e.normal = {0.0, -1.0};
  e.normalImpulse = 1.0;
  e.tangentImpulse = 0.5;  // along tau = z x n = (1, 0)
  Recorder r;
  drawImpacts(r, twoBalls(), states(), {e});
  ASSERT_EQ(r.calls.size(), 4u);  // normal + one arrow
  const Vec2 arrow = r.calls[1].b - r.calls[1].a;
  // The ball receives -P = -(lambda_n n + lambda_t tau) = (-0.5, +1): up, off the floor.
  EXPECT_GT(arrow.y(), 0.0);
  EXPECT_NEAR(arrow.x() / arrow.y(), -0.5, 1e-12);
}

}  // namespace
}  // namespace particles::viewer
