#include "particles/swept_ball.h"

#include <algorithm>
#include <cmath>

namespace particles {

// Ball b relative to ball a: d = xb - xa, w = vb - va, reach ra + rb.
std::optional<SweptHit> sweepBalls(const Vec2& xa, const Vec2& va, double ra, const Vec2& xb,
                                   const Vec2& vb, double rb, double dt) {
  const Vec2 d = xb - xa, w = vb - va;
  const auto t = timeOfImpact(d, w, ra + rb, dt);
  if (!t) return std::nullopt;
  const Vec2 at = d + *t * w;
  return SweptHit{*t, at.normalized()};
}

void SweptPairFinder::consider(std::span<const Vec2> position, std::span<const Vec2> velocity,
                               std::span<const double> radius, double dt, int a, int b,
                               std::vector<SweptPair>& out) {
  BallPair touching;
  // A pair touching at the start is the discrete contact's, with its slop.
  if (touchBalls(position[a], radius[a], position[b], radius[b], touching)) return;
  const auto hit =
      sweepBalls(position[a], velocity[a], radius[a], position[b], velocity[b], radius[b], dt);
  if (hit) out.push_back({a, b, hit->time, hit->normal});
}

void SweptPairFinder::find(std::span<const Vec2> position, std::span<const Vec2> velocity,
                           std::span<const double> radius, double dt, bool grid,
                           std::vector<SweptPair>& out) {
  out.clear();
  const int n = static_cast<int>(position.size());
  if (grid) {
    centre_.resize(position.size());
    reach_.resize(position.size());
    for (std::size_t i = 0; i < position.size(); ++i) {
      centre_[i] = position[i] + 0.5 * dt * velocity[i];
      reach_[i] = radius[i] + 0.5 * dt * velocity[i].norm();
    }
    // Two disks that meet during the step both cover the meeting point, so
    // their swept bounds overlap: the candidates hold every swept pair.
    grid_.findPairs(centre_, reach_, candidates_);
    for (const BallPair& p : candidates_) consider(position, velocity, radius, dt, p.a, p.b, out);
  } else {
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b) consider(position, velocity, radius, dt, a, b, out);
  }
  std::sort(out.begin(), out.end(), [](const SweptPair& p, const SweptPair& q) {
    if (p.time != q.time) return p.time < q.time;
    return p.a != q.a ? p.a < q.a : p.b < q.b;
  });
}

std::size_t SweptPairFinder::memoryBytes() const {
  return grid_.memoryBytes() + centre_.capacity() * sizeof(Vec2) +
         reach_.capacity() * sizeof(double) + candidates_.capacity() * sizeof(BallPair);
}

}  // namespace particles
