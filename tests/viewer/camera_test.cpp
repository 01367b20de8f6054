// The view transform: y flips, the scene fits, zoom keeps the cursor's point.
#include <gtest/gtest.h>

#include "particles/reference/box2d_world.h"
#include "particles/viewer/camera.h"
#include "particles/world.h"

namespace particles::viewer {
namespace {

Camera camera(Vec2 centre, double scale, Viewport v) {
  Camera c;
  c.centre = centre;
  c.scale = scale;
  c.viewport = v;
  return c;
}

TEST(Camera, ProjectsWithTheHandoutsFormulaAndFlipsY) {
  const Camera c = camera({1.0, 2.0}, 100.0, {0, 0, 800, 600});
  // screen = (x - cx) * scale + w/2, h/2 - (y - cy) * scale
  EXPECT_EQ(c.toScreen({1.0, 2.0}), Vec2(400.0, 300.0));
  EXPECT_EQ(c.toScreen({2.0, 2.0}), Vec2(500.0, 300.0));  // +x is right
  EXPECT_EQ(c.toScreen({1.0, 3.0}), Vec2(400.0, 200.0));  // +y is up: smaller screen y
  EXPECT_EQ(c.toScreen({0.5, 1.5}), Vec2(350.0, 350.0));
}

TEST(Camera, ViewportOffsetAndInverse) {
  const Camera c = camera({-3.0, 0.25}, 37.5, {640, 10, 640, 480});
  EXPECT_EQ(c.toScreen({-3.0, 0.25}), Vec2(960.0, 250.0));
  for (const Vec2& p : {Vec2(0.0, 0.0), Vec2(-7.25, 3.5), Vec2(1e3, -2e2)})
    EXPECT_LT((c.toWorld(c.toScreen(p)) - p).norm(), 1e-12 * (1.0 + p.norm()));
  EXPECT_TRUE(c.contains({640.0, 10.0}));
  EXPECT_FALSE(c.contains({639.9, 100.0}));
  EXPECT_FALSE(c.contains({1280.0, 100.0}));
}

TEST(Camera, FitShowsTheWholeSceneWithItsMargin) {
  SceneDef scene;
  scene.walls = boxWalls({0.0, 0.0}, {4.0, 3.0});
  BallDef ball;
  ball.position = {1.0, 1.0};
  ball.radius = 0.3;
  scene.balls.push_back(ball);
  const Bounds b = sceneBounds(scene);
  EXPECT_EQ(b.lo, Vec2(0.0, 0.0));
  EXPECT_EQ(b.hi, Vec2(4.0, 3.0));
  const Camera c = fitCamera(b, {0, 0, 800, 800}, {});
  EXPECT_EQ(c.centre, Vec2(2.0, 1.5));
  EXPECT_DOUBLE_EQ(c.scale, (1.0 - 2.0 * kFitMargin) * 800.0 / 4.0);  // width limits
  const Vec2 lo = c.toScreen(b.lo), hi = c.toScreen(b.hi);
  EXPECT_NEAR(lo.x(), kFitMargin * 800.0, 1e-9);
  EXPECT_GT(lo.y(), hi.y());  // the bottom of the world is lower on screen
  EXPECT_TRUE(c.contains(lo) && c.contains(hi));
}

TEST(Camera, ALoneBallGetsRoomAroundIt) {
  SceneDef scene;
  BallDef ball;
  ball.position = {5.0, -1.0};
  ball.radius = 0.5;
  scene.balls.push_back(ball);
  const Bounds b = sceneBounds(scene);
  EXPECT_EQ(b.hi - b.lo, Vec2(2.0, 2.0));  // four radii
  EXPECT_EQ(0.5 * (b.lo + b.hi), ball.position);
}

TEST(Camera, RunBoundsCoverTheWholeFlight) {
  // A projectile from (0, 1) at (3, 4) m/s for 0.8 s: it lands near x = 2.4
  // and peaks near y = 1 + 16 / (2 g) = 1.82.
  SceneDef scene;
  scene.gravity = {0.0, -9.81};
  scene.duration = 0.8;
  BallDef ball;
  ball.position = {0.0, 1.0};
  ball.velocity = {3.0, 4.0};
  ball.radius = 0.1;
  scene.balls.push_back(ball);
  const Bounds b = runBounds(scene);
  // The engine lands at x = 2.4 to rounding; the bounds also cover the Box2D
  // twin, whose float positions may drift by up to 800 steps x one float ulp
  // of 2.4 (2.4e-7 m), i.e. 2e-4 m, past it.
  EXPECT_GE(b.hi.x(), 2.4 + 0.1 - 1e-9);
  EXPECT_LE(b.hi.x(), 2.4 + 0.1 + 2e-4);
  EXPECT_NEAR(b.hi.y(), 1.0 + 16.0 / (2.0 * 9.81) + 0.1, 1e-2);
  EXPECT_LE(b.lo.x(), -0.1);
  // A budget of one step per ball stops the run early.
  EXPECT_LT(runBounds(scene, 1).hi.x(), 0.5);
}

TEST(Camera, RunBoundsCoverTheBox2DTwinsRunToo) {
  // Newton's cradle: the engine's simultaneous contacts send only the last
  // ball away; Box2D's sequential solver also moves the first ball back
  // (docs/box2d-twin.md). Whatever either engine does must be in view.
  SceneDef scene;
  scene.duration = 0.5;
  scene.dt = 1e-3;
  for (int i = 0; i < 5; ++i) {
    BallDef ball;
    ball.position = {1.0 * i, 0.0};
    scene.balls.push_back(ball);
  }
  scene.balls[0].position = {-1.0, 0.0};
  scene.balls[0].velocity = {2.0, 0.0};
  const Bounds b = runBounds(scene);
  reference::Box2DWorld twin(scene, reference::Box2DSettings::forScene(scene));
  World engine(scene);
  for (long long s = 0; s < scene.stepCount(); ++s) {
    twin.step();
    engine.step();
    for (std::size_t i = 0; i < scene.balls.size(); ++i) {
      for (const Vec2& x : {twin.ball(i).position, engine.ball(i).position}) {
        EXPECT_LE(b.lo.x(), x.x() - 0.5 + 1e-12);
        EXPECT_GE(b.hi.x(), x.x() + 0.5 - 1e-12);
        EXPECT_LE(b.lo.y(), x.y() - 0.5 + 1e-12);
        EXPECT_GE(b.hi.y(), x.y() + 0.5 - 1e-12);
      }
    }
  }
}

TEST(Camera, SideBySideSplitsTheWidth) {
  const std::vector<Viewport> one = viewportsFor(ViewMode::Overlay, 801, 600);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].width, 801);
  const std::vector<Viewport> two = viewportsFor(ViewMode::Side, 801, 600);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0].left, 0);
  EXPECT_EQ(two[0].width, 400);
  EXPECT_EQ(two[1].left, 400);
  EXPECT_EQ(two[1].width, 400);
  const Bounds b{{0.0, 0.0}, {1.0, 1.0}};
  const std::vector<Camera> cams = camerasFor(ViewMode::Side, b, 801, 600, {});
  // The same world point lands at the same place within each half.
  const Vec2 p(0.25, 0.75);
  EXPECT_EQ(cams[0].scale, cams[1].scale);
  EXPECT_NEAR(cams[1].toScreen(p).x() - cams[0].toScreen(p).x(), 400.0, 1e-9);
  EXPECT_EQ(cams[0].toScreen(p).y(), cams[1].toScreen(p).y());
}

TEST(Camera, ZoomKeepsThePointUnderTheCursor) {
  const Bounds b{{0.0, 0.0}, {4.0, 3.0}};
  CameraControl control;
  const Camera before = fitCamera(b, {0, 0, 800, 600}, control);
  const Vec2 cursor(123.0, 456.0);
  const Vec2 world = before.toWorld(cursor);
  zoomAt(control, before, cursor, 2.0);
  const Camera after = fitCamera(b, {0, 0, 800, 600}, control);
  EXPECT_DOUBLE_EQ(after.scale, 2.0 * before.scale);
  EXPECT_LT((after.toWorld(cursor) - world).norm(), 1e-12);
}

TEST(Camera, InsetsKeepTheSceneBetweenThem) {
  const Bounds b{{0.0, 0.0}, {4.0, 3.0}};
  const FitInsets insets{100.0, 40.0};
  CameraControl control;
  const Camera c = fitCamera(b, {0, 0, 800, 600}, control, insets);
  const double usable = 1.0 - 2.0 * kFitMargin;
  EXPECT_DOUBLE_EQ(c.scale, usable * (600.0 - 140.0) / 3.0);  // height limits now
  EXPECT_NEAR(c.toScreen(b.hi).y(), 100.0 + kFitMargin * 460.0, 1e-9);
  EXPECT_NEAR(c.toScreen(b.lo).y(), 560.0 - kFitMargin * 460.0, 1e-9);
  // Zoom still keeps the cursor's point.
  const Vec2 cursor(700.0, 50.0), world = c.toWorld(cursor);
  zoomAt(control, c, cursor, 0.5);
  EXPECT_LT((fitCamera(b, {0, 0, 800, 600}, control, insets).toWorld(cursor) - world).norm(),
            1e-12);
}

TEST(Camera, PanFollowsTheMouse) {
  const Bounds b{{0.0, 0.0}, {4.0, 3.0}};
  CameraControl control;
  const Camera before = fitCamera(b, {0, 0, 800, 600}, control);
  const Vec2 grabbed = before.toWorld({300.0, 300.0});
  panBy(control, before, {40.0, -25.0});
  const Camera after = fitCamera(b, {0, 0, 800, 600}, control);
  // The world point that was under the mouse moved with it.
  EXPECT_LT((after.toScreen(grabbed) - Vec2(340.0, 275.0)).norm(), 1e-9);
}

TEST(ViewMode, CyclesAndParses) {
  EXPECT_EQ(nextMode(ViewMode::Engine, true), ViewMode::Box2D);
  EXPECT_EQ(nextMode(ViewMode::Box2D, true), ViewMode::Overlay);
  EXPECT_EQ(nextMode(ViewMode::Overlay, true), ViewMode::Side);
  EXPECT_EQ(nextMode(ViewMode::Side, true), ViewMode::Engine);
  EXPECT_EQ(nextMode(ViewMode::Engine, false), ViewMode::Engine);
  for (ViewMode m : {ViewMode::Engine, ViewMode::Box2D, ViewMode::Overlay, ViewMode::Side})
    EXPECT_EQ(parseMode(modeName(m)), m);
  EXPECT_FALSE(parseMode("both"));
}

}  // namespace
}  // namespace particles::viewer
