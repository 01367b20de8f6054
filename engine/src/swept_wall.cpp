#include "particles/swept_wall.h"

#include <cmath>

namespace particles {

// The smaller root of (w.w) t^2 + 2 (d.w) t + (d.d - reach^2) = 0. Every test
// is written so that a NaN fails it.
std::optional<double> timeOfImpact(const Vec2& d, const Vec2& w, double reach, double dt) {
  const double a = w.squaredNorm(), b = d.dot(w), c = d.squaredNorm() - reach * reach;
  if (!(c > 0.0) || !(b < 0.0) || a == 0.0) return std::nullopt;  // touching, or not closing
  const double disc = b * b - a * c;
  if (!(disc >= 0.0)) return std::nullopt;      // the closest approach stays beyond reach
  const double t = c / (-b + std::sqrt(disc));  // the smaller root, without cancellation
  if (!(t <= dt)) return std::nullopt;
  return t;
}

std::optional<SweptHit> sweepAgainstWall(const Vec2& x, const Vec2& v, double r,
                                         const WallDef& wall, double dt) {
  const Vec2 ab = wall.b - wall.a;
  const double len2 = ab.squaredNorm();
  std::optional<SweptHit> best;
  if (len2 > 0.0) {
    // The flat sides: the signed distance s0 along the unit normal must fall
    // to r while the centre's foot stays within the segment.
    const Vec2 unit = perpLeft(ab) / std::sqrt(len2);
    const double s0 = (x - wall.a).dot(unit), sv = v.dot(unit);
    if (std::fabs(s0) > r && s0 * sv < 0.0) {
      const double t = (std::fabs(s0) - r) / std::fabs(sv);
      const double u = (x + t * v - wall.a).dot(ab) / len2;
      if (t <= dt && u >= 0.0 && u <= 1.0) best = SweptHit{t, s0 > 0.0 ? Vec2(-unit) : unit};
    }
  }
  // The round ends (the only shape of a point wall).
  for (const Vec2& e : {wall.a, wall.b}) {
    const auto t = timeOfImpact(x - e, v, r, dt);
    if (t && (!best || *t < best->time)) best = SweptHit{*t, (e - (x + *t * v)).normalized()};
  }
  return best;
}

}  // namespace particles
