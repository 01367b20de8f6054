// Helpers shared by the Box2D twin's tests: float rounding as Box2D sees it,
// and small scenes.
#pragma once

#include <cmath>
#include <limits>

#include "particles/scene.h"

namespace particles::reference::testing {

// The value Box2D stores for a double it is given, widened back.
inline double asFloat(double x) {
  return static_cast<float>(x);
}

// Spacing of floats around |x|: one rounding of a float result near x is off
// by at most half of it.
inline double floatUlp(double x) {
  const float f = static_cast<float>(std::abs(x));
  return std::nextafter(f, std::numeric_limits<float>::infinity()) - f;
}

// Relative rounding of one float operation.
inline constexpr double kFloatEps = std::numeric_limits<float>::epsilon();

inline BallDef ball(const Vec2& position, const Vec2& velocity, double radius = 0.5,
                    double mass = 1.0) {
  BallDef b;
  b.position = position;
  b.velocity = velocity;
  b.radius = radius;
  b.mass = mass;
  return b;
}

// Scene with no walls, no gravity, the given balls and dt = 1 ms.
inline SceneDef openScene(std::vector<BallDef> balls, const ContactMaterial& contact = {1.0, 0.0}) {
  SceneDef s;
  s.dt = 1e-3;
  s.duration = 1.0;
  s.contact = contact;
  s.balls = std::move(balls);
  return s;
}

}  // namespace particles::reference::testing
