#include "box2d_peak.h"

#include <algorithm>
#include <cmath>

namespace particles::reference {
namespace {

// s of [start, end) that falls inside the run [0, duration].
double activeTime(const ForceDef& f, double duration) {
  return std::max(0.0, std::min(f.end, duration) - std::max(f.start, 0.0));
}

}  // namespace

Peak estimatePeak(const SceneDef& scene, std::size_t i) {
  const BallDef& b = scene.balls[i];
  Peak peak{b.velocity.norm() + scene.gravity.norm() * scene.duration, std::abs(b.angularVelocity)};
  for (const ForceDef& f : scene.forces) {
    if (f.ball != static_cast<int>(i)) continue;
    const double t = activeTime(f, scene.duration);
    if (t <= 0.0) continue;
    if (f.type == ForceType::Pull) {
      // A spring from rest at distance d reaches sqrt(k/m) d (energy).
      peak.speed += std::sqrt(std::abs(f.stiffness) / b.mass) * (f.target - b.position).norm();
    } else {
      peak.speed += f.force.norm() / b.mass * t;
      peak.spin += std::abs(f.torque) / b.resolvedInertia() * t;
    }
  }
  return peak;
}

}  // namespace particles::reference
