// The drawing interface between the simulation and a renderer, in the style
// of Box2D v3's b2DebugDraw: world coordinates (m, y up, angles
// counter-clockwise) in, pixels out. The painter (painter.h) draws scenes
// through it; SfmlDebugDraw (sfml_draw.h) implements it. The engine itself
// knows nothing of drawing.
#pragma once

#include <cstdint>

#include "particles/types.h"

namespace particles::viewer {

// An 8-bit RGBA colour (no SFML type, so the painter stays SFML-free).
struct Color {
  std::uint8_t r = 0, g = 0, b = 0;
  std::uint8_t a = 255;  // 255 opaque
  friend bool operator==(const Color&, const Color&) = default;
};

class DebugDraw {
 public:
  virtual ~DebugDraw() = default;

  // The outline of a circle of `radius` m around `centre` (m).
  virtual void circle(const Vec2& centre, double radius, Color color) = 0;
  // A filled circle with a marker: the radius from the centre at `angle`
  // (rad, counter-clockwise from +x), drawn in `marker`. Box2D's
  // DrawSolidCircle, whose axis line shows a body's rotation.
  virtual void solidCircle(const Vec2& centre, double radius, double angle, Color fill,
                           Color marker) = 0;
  // A line segment from a to b (m).
  virtual void segment(const Vec2& a, const Vec2& b, Color color) = 0;
  // A dot of `sizePixels` px at p (m): stays visible at any zoom.
  virtual void point(const Vec2& p, double sizePixels, Color color) = 0;
};

// An arrow from `from` to `to` (m): a segment and a two-stroke head whose
// strokes are `head` m long (a quarter of the length when that is shorter).
void drawArrow(DebugDraw& draw, const Vec2& from, const Vec2& to, double head, Color color);

}  // namespace particles::viewer
