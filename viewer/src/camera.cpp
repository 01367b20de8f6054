#include "particles/viewer/camera.h"

#include <algorithm>
#include <stdexcept>

#include "particles/reference/box2d_world.h"
#include "particles/world.h"

namespace particles::viewer {

Vec2 Camera::toScreen(const Vec2& world) const {
  return {viewport.left + 0.5 * viewport.width + (world.x() - centre.x()) * scale,
          viewport.top + 0.5 * viewport.height - (world.y() - centre.y()) * scale};
}

Vec2 Camera::toWorld(const Vec2& screen) const {
  return {centre.x() + (screen.x() - viewport.left - 0.5 * viewport.width) / scale,
          centre.y() - (screen.y() - viewport.top - 0.5 * viewport.height) / scale};
}

bool Camera::contains(const Vec2& screen) const {
  return screen.x() >= viewport.left && screen.x() < viewport.left + viewport.width &&
         screen.y() >= viewport.top && screen.y() < viewport.top + viewport.height;
}

Bounds sceneBounds(const SceneDef& scene) {
  if (scene.balls.empty() && scene.walls.empty()) return {{-1.0, -1.0}, {1.0, 1.0}};
  constexpr double inf = std::numeric_limits<double>::infinity();
  Bounds b{{inf, inf}, {-inf, -inf}};
  double largestRadius = 0.0;
  auto grow = [&b](const Vec2& lo, const Vec2& hi) {
    b.lo = b.lo.cwiseMin(lo);
    b.hi = b.hi.cwiseMax(hi);
  };
  for (const BallDef& ball : scene.balls) {
    const Vec2 r(ball.radius, ball.radius);
    grow(ball.position - r, ball.position + r);
    largestRadius = std::max(largestRadius, ball.radius);
  }
  for (const WallDef& w : scene.walls) grow(w.a.cwiseMin(w.b), w.a.cwiseMax(w.b));
  // A pull's target is where its ball is headed: keep it in view.
  for (const ForceDef& f : scene.forces)
    if (f.type == ForceType::Pull) grow(f.target, f.target);
  // A lone ball (or a lone wall) would fill the whole view; show some room
  // around it: at least four of the largest radii, or 1 m.
  const double least = std::max(4.0 * largestRadius, scene.balls.empty() ? 1.0 : 0.0);
  const Vec2 mid = 0.5 * (b.lo + b.hi);
  const Vec2 half = (0.5 * (b.hi - b.lo)).cwiseMax(Vec2(0.5 * least, 0.5 * least));
  return {mid - half, mid + half};
}

namespace {

// Grows b by every ball's disk at each of `steps` steps of `world` (the engine
// or its Box2D twin: both have step(), ballCount() and ball(i)).
template <class AnyWorld>
void growByRun(AnyWorld& world, const SceneDef& scene, long long steps, Bounds& b) {
  for (long long s = 0; s < steps; ++s) {
    world.step();
    for (std::size_t i = 0; i < world.ballCount(); ++i) {
      const Vec2 x = world.ball(i).position;
      if (!x.allFinite()) continue;
      const Vec2 r(scene.balls[i].radius, scene.balls[i].radius);
      b.lo = b.lo.cwiseMin(x - r);
      b.hi = b.hi.cwiseMax(x + r);
    }
  }
}

}  // namespace

Bounds runBounds(const SceneDef& scene, long long maxBallSteps) {
  Bounds b = sceneBounds(scene);
  if (scene.balls.empty()) return b;
  const long long balls = static_cast<long long>(scene.balls.size());
  const long long steps = std::min(scene.stepCount(), maxBallSteps / balls);
  World world(scene);
  growByRun(world, scene, steps, b);
  // The Box2D twin too: where the engines disagree (a Newton's cradle, say)
  // its balls go where the engine's never do, and overlay and side-by-side
  // modes must show them.
  try {
    reference::Box2DWorld twin(scene, reference::Box2DSettings::forScene(scene));
    growByRun(twin, scene, steps, b);
  } catch (const std::invalid_argument&) {
    // A scene Box2D cannot take: the viewer shows the engine alone.
  }
  return b;
}

Camera fitCamera(const Bounds& bounds, const Viewport& viewport, const CameraControl& control,
                 const FitInsets& insets) {
  const Vec2 extent = (bounds.hi - bounds.lo).cwiseMax(Vec2(1e-9, 1e-9));
  const double usable = 1.0 - 2.0 * kFitMargin;
  const double height = std::max(1.0, viewport.height - insets.top - insets.bottom);
  const double fit = std::min(usable * viewport.width / extent.x(), usable * height / extent.y());
  // The bounds' centre goes to the middle of the area between the insets,
  // (top - bottom) / 2 px below the viewport's centre. The shift is in fit
  // pixels, not zoomed ones, so that zoomAt can keep a point by panning.
  const Vec2 shift(0.0, 0.5 * (insets.top - insets.bottom) / fit);
  Camera c;
  c.centre = 0.5 * (bounds.lo + bounds.hi) + shift + control.pan;
  c.scale = fit * control.zoom;
  c.viewport = viewport;
  return c;
}

std::vector<Viewport> viewportsFor(ViewMode mode, int width, int height) {
  width = std::max(width, 2);
  height = std::max(height, 1);
  if (mode != ViewMode::Side) return {{0, 0, width, height}};
  // Equal halves (an odd last column stays empty), so both worlds are drawn
  // at the same scale.
  const int half = width / 2;
  return {{0, 0, half, height}, {half, 0, half, height}};
}

std::vector<Camera> camerasFor(ViewMode mode, const Bounds& bounds, int width, int height,
                               const CameraControl& control, const FitInsets& insets) {
  std::vector<Camera> cameras;
  for (const Viewport& v : viewportsFor(mode, width, height))
    cameras.push_back(fitCamera(bounds, v, control, insets));
  return cameras;
}

// The zoomed camera keeps toWorld(screen); its centre moves by exactly what
// the pan must add, since the fitted part of the centre does not depend on
// the zoom.
void zoomAt(CameraControl& control, const Camera& camera, const Vec2& screen, double factor) {
  Camera zoomed = camera;
  zoomed.scale *= factor;
  const Vec2 offset = (screen - zoomed.toScreen(zoomed.centre)) / zoomed.scale;
  zoomed.centre = camera.toWorld(screen) - Vec2(offset.x(), -offset.y());
  control.zoom *= factor;
  control.pan += zoomed.centre - camera.centre;
}

void panBy(CameraControl& control, const Camera& camera, const Vec2& screenDelta) {
  // Screen y points down and world y up: a drag down moves the view's centre up.
  control.pan += Vec2(-screenDelta.x(), screenDelta.y()) / camera.scale;
}

}  // namespace particles::viewer
