// Continuous collision between two moving balls (time of impact), for
// SolverSettings::sweptBalls: two balls fast enough to pass through each
// other within one step are caught at the moment their surfaces meet.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "particles/broad_phase.h"
#include "particles/swept_wall.h"

namespace particles {

// The first time t in [0, dt] at which ball b (centre xb, velocity vb,
// radius rb) touches ball a, both moving with constant velocity, if they are
// apart at the start and approaching. SweptHit::normal is then the unit
// vector from a's centre to b's at t. nullopt if they touch already, move
// apart, or miss within the step.
std::optional<SweptHit> sweepBalls(const Vec2& xa, const Vec2& va, double ra, const Vec2& xb,
                                   const Vec2& vb, double rb, double dt);

// A pair apart at the start of the step that sweepBalls() brings into
// contact within it.
struct SweptPair {
  int a = 0;  // ball index, a < b
  int b = 0;
  double time = 0.0;      // s after the start of the step
  Vec2 normal{1.0, 0.0};  // unit, from a to b at that time
};

// Finds every swept pair among balls that do not touch at the start (the
// touching pairs are findPairsBruteForce's), ordered by (time, a, b), so the
// solver meets a fast ball's first impact before the ones behind it. Keeps
// its buffers between calls.
class SweptPairFinder {
 public:
  // grid = false: every pair is swept (brute force, small scenes). grid =
  // true: the uniform grid on each ball's swept bounds (the circle around
  // its mid-step centre x + v dt/2 of radius r + |v| dt/2, which holds every
  // position of its disk during the step), so no fast pair is missed; the
  // same pairs as brute force.
  void find(std::span<const Vec2> position, std::span<const Vec2> velocity,
            std::span<const double> radius, double dt, bool grid, std::vector<SweptPair>& out);
  std::size_t memoryBytes() const;

 private:
  void consider(std::span<const Vec2> position, std::span<const Vec2> velocity,
                std::span<const double> radius, double dt, int a, int b,
                std::vector<SweptPair>& out);

  BroadPhase grid_;
  std::vector<Vec2> centre_;
  std::vector<double> reach_;
  std::vector<BallPair> candidates_;
};

}  // namespace particles
