// Basic types shared by the whole engine. SI units everywhere: metres,
// kilograms, seconds, radians; y points up, angles are counter-clockwise.
#pragma once

#include <Eigen/Core>
#include <limits>

namespace particles {

using Vec2 = Eigen::Vector2d;

// Friction coefficient that means "no slip": the tangential impulse is never
// clamped, so the contact surfaces leave with equal tangential velocities.
inline constexpr double kNoSlip = std::numeric_limits<double>::infinity();

// 2D cross product of two vectors: the z component of a x b.
inline double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// z x v: rotates v by +90 degrees (counter-clockwise).
inline Vec2 perpLeft(const Vec2& v) {
  return Vec2(-v.y(), v.x());
}

}  // namespace particles
