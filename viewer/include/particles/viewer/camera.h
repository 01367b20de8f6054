// The view transform from the world (metres, y up) to pixels (y down), and
// how the viewer lays out its one or two viewports. Pure functions of plain
// data, so the tests can compute where a ball must appear without a window.
#pragma once

#include <vector>

#include "particles/scene.h"
#include "particles/viewer/view_mode.h"

namespace particles::viewer {

// A rectangle of the render target, in pixels from its top-left corner.
struct Viewport {
  int left = 0;    // px
  int top = 0;     // px
  int width = 1;   // px, > 0
  int height = 1;  // px, > 0
};

// What a camera shows: the world point at the viewport's centre and the zoom.
// The y axis flips here and only here, so every drawing below works in world
// coordinates and a counter-clockwise angle stays counter-clockwise on screen.
struct Camera {
  Vec2 centre{0.0, 0.0};  // m, world point drawn at the viewport's centre
  double scale = 100.0;   // px/m, > 0
  Viewport viewport;

  // screen = (x - cx) * scale + w/2, h/2 - (y - cy) * scale, offset by the
  // viewport's corner. Pixel (i, j) covers [i, i+1) x [j, j+1).
  Vec2 toScreen(const Vec2& world) const;
  Vec2 toWorld(const Vec2& screen) const;
  bool contains(const Vec2& screen) const;  // screen point inside the viewport
};

// The axis-aligned box around every wall and every ball at its start, m.
struct Bounds {
  Vec2 lo{0.0, 0.0};
  Vec2 hi{0.0, 0.0};
};
Bounds sceneBounds(const SceneDef& scene);

// sceneBounds grown by every ball's disk at every step of the engine's run of
// the scene's duration, and of its Box2D twin's run, so that the first view
// shows all that either engine will do.
// The run stops after maxBallSteps (steps times balls) to bound the cost on
// big scenes; non-finite states are ignored.
inline constexpr long long kBoundsBallSteps = 2000000;
Bounds runBounds(const SceneDef& scene, long long maxBallSteps = kBoundsBallSteps);

// What the user changed with the mouse: a pan (m) and a zoom factor on top
// of the camera that fits the scene, so that switching modes (one viewport or
// two) refits the scene and keeps the user's pan and zoom.
struct CameraControl {
  Vec2 pan{0.0, 0.0};  // m, added to the fitted centre
  double zoom = 1.0;   // dimensionless, multiplies the fitted scale
};

// Pixels at the top and bottom of a viewport that the fit leaves to text
// (the readout), so that the text does not cover the scene.
struct FitInsets {
  double top = 0.0;     // px
  double bottom = 0.0;  // px
};

// The camera that shows `bounds` whole inside `viewport` less `insets`, with a
// margin of kFitMargin of that area on each side, then applies `control`.
Camera fitCamera(const Bounds& bounds, const Viewport& viewport, const CameraControl& control,
                 const FitInsets& insets = {});

// Fraction of the viewport left free around the scene on each side.
inline constexpr double kFitMargin = 0.06;

// The viewports of a target of width x height pixels in `mode`: one for every
// mode except Side, which has the engine on the left half and Box2D on the
// right half, of equal widths (an odd last column stays empty).
std::vector<Viewport> viewportsFor(ViewMode mode, int width, int height);

// One camera per viewport of `mode`, all showing the same part of the world.
std::vector<Camera> camerasFor(ViewMode mode, const Bounds& bounds, int width, int height,
                               const CameraControl& control, const FitInsets& insets = {});

// Zooms by `factor` (> 1 closer) keeping the world point under `screen` where
// it is on screen; `camera` is the camera the cursor is over.
void zoomAt(CameraControl& control, const Camera& camera, const Vec2& screen, double factor);
// Pans so that the world follows a mouse move of `screenDelta` pixels.
void panBy(CameraControl& control, const Camera& camera, const Vec2& screenDelta);

}  // namespace particles::viewer
