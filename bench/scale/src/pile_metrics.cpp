#include "particles/pile/pile_metrics.h"

#include <algorithm>

#include "particles/broad_phase.h"

namespace particles::pile {

long long countOutside(std::span<const BallState> balls, const Vec2& lo, const Vec2& hi) {
  long long out = 0;
  for (const BallState& b : balls) {
    const Vec2& x = b.position;
    // Written so that a NaN centre counts as outside.
    out += !(x.x() >= lo.x() && x.x() <= hi.x() && x.y() >= lo.y() && x.y() <= hi.y());
  }
  return out;
}

OverlapFigures measureOverlap(std::span<const BallState> balls, std::span<const BallDef> defs) {
  std::vector<Vec2> position(balls.size());
  std::vector<double> radius(balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i) {
    position[i] = balls[i].position;
    radius[i] = defs[i].radius;
  }
  // The engine's own pair finder (held to brute force by the BroadPhase
  // tests), so "touching" means exactly what it means to the engine.
  std::vector<BallPair> pairs;
  BroadPhase grid;
  grid.findPairs(position, radius, pairs);
  OverlapFigures f;
  double sum = 0.0;
  for (const BallPair& p : pairs) {
    const double fraction = std::max(0.0, p.overlap) / std::min(radius[p.a], radius[p.b]);
    f.max = std::max(f.max, fraction);
    sum += fraction;
  }
  f.touchingPairs = static_cast<long long>(pairs.size());
  f.mean = pairs.empty() ? 0.0 : sum / static_cast<double>(pairs.size());
  return f;
}

double kineticEnergy(std::span<const BallState> balls, std::span<const BallDef> defs) {
  double e = 0.0;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const BallDef& d = defs[i];
    const BallState& b = balls[i];
    e += 0.5 * d.mass * b.velocity.squaredNorm() +
         0.5 * d.resolvedInertia() * b.angularVelocity * b.angularVelocity;
  }
  return e;
}

double restEnergy(std::span<const BallDef> defs) {
  double mass = 0.0;
  for (const BallDef& d : defs) mass += d.mass;
  return 0.5 * mass * kRestSpeed * kRestSpeed;
}

std::optional<long long> restStep(std::span<const double> energies, double threshold) {
  if (energies.empty() || energies.back() > threshold) return std::nullopt;
  long long s = static_cast<long long>(energies.size()) - 1;
  while (s > 0 && energies[static_cast<std::size_t>(s - 1)] <= threshold) --s;
  return s;
}

}  // namespace particles::pile
