// Finding touching pairs: brute force for a handful of balls, a uniform grid
// beyond that. Both return exactly the same pairs in the same order (sorted by
// (a, b)), so the choice never changes a result; the brute-force finder is the
// test oracle for the grid.
#pragma once

#include <span>
#include <vector>

#include "particles/scene.h"
#include "particles/types.h"

namespace particles {

// Two balls whose disks touch or overlap: |x_b - x_a| <= r_a + r_b (within a
// relative slop of 1e-9 for rounding), a < b.
struct BallPair {
  int a = 0;
  int b = 0;
  Vec2 normal{1.0, 0.0};  // unit, from a to b
  double overlap = 0.0;   // m, r_a + r_b - |x_b - x_a| (>= -slop)
};

// A ball touching a wall: distance from its centre to the segment <= r.
struct WallHit {
  int ball = 0;
  int wall = 0;
  Vec2 normal{0.0, -1.0};  // unit, from the ball's centre to the wall
  double overlap = 0.0;    // m, r - distance (>= -slop)
};

// Geometry of ball i against ball j; returns false when they do not touch.
bool touchBalls(const Vec2& xa, double ra, const Vec2& xb, double rb, BallPair& pair);
// Geometry of a ball against a wall segment; returns false when apart.
bool touchWall(const Vec2& x, double r, const WallDef& wall, WallHit& hit);

void findPairsBruteForce(std::span<const Vec2> position, std::span<const double> radius,
                         std::vector<BallPair>& out);

// A uniform grid with cells as wide as the largest ball's diameter, rebuilt
// each call; keeps its buffers between calls.
class BroadPhase {
 public:
  void findPairs(std::span<const Vec2> position, std::span<const double> radius,
                 std::vector<BallPair>& out);
  // Bytes held by the grid's buffers (their capacity).
  std::size_t memoryBytes() const;

 private:
  std::vector<int> cellStart_;  // prefix sums over cells (counting sort)
  std::vector<int> cellBalls_;  // ball indices grouped by cell
  std::vector<int> cellFill_;   // next free slot per cell while sorting
  std::vector<int> ballCell_;   // cell of each ball
};

void findWallHits(std::span<const Vec2> position, std::span<const double> radius,
                  std::span<const WallDef> walls, std::vector<WallHit>& out);

}  // namespace particles
