#include "particles/broad_phase.h"

#include <algorithm>
#include <cmath>

namespace particles {
namespace {
// Bodies within this fraction of their reach count as touching. A pair left
// exactly touching by the position pass sits at |d| = r_a + r_b up to
// rounding; without the slop, rounding would decide whether a resting contact
// exists, and a ball missed that way would gather speed while the projection
// holds it in place.
constexpr double kTouchSlop = 1e-9;
}  // namespace

bool touchBalls(const Vec2& xa, double ra, const Vec2& xb, double rb, BallPair& pair) {
  const Vec2 d = xb - xa;
  const double reach = ra + rb;
  const double dist2 = d.squaredNorm();
  const double detect = reach * (1.0 + kTouchSlop);
  if (dist2 > detect * detect) return false;
  const double dist = std::sqrt(dist2);
  // Coincident centres have no normal; any fixed direction keeps the step
  // deterministic, and the position pass then separates them along it.
  pair.normal = dist > 0.0 ? Vec2(d / dist) : Vec2(1.0, 0.0);
  pair.overlap = reach - dist;
  return true;
}

bool touchWall(const Vec2& x, double r, const WallDef& wall, WallHit& hit) {
  const Vec2 ab = wall.b - wall.a;
  const double len2 = ab.squaredNorm();
  const double s = len2 > 0.0 ? (x - wall.a).dot(ab) / len2 : 0.0;
  Vec2 d;
  if (s > 0.0 && s < 1.0) {
    // Inside the segment, go straight along its normal: a + s ab would carry
    // rounding of the order of eps times the wall's length into the normal,
    // and a floor's normal should be exactly (0, -1).
    const Vec2 unit = perpLeft(ab) / std::sqrt(len2);
    d = -(x - wall.a).dot(unit) * unit;
  } else {
    d = (s <= 0.0 ? wall.a : wall.b) - x;
  }
  const double dist2 = d.squaredNorm();
  const double detect = r * (1.0 + kTouchSlop);
  if (dist2 > detect * detect) return false;
  const double dist = std::sqrt(dist2);
  // A one-sided wall's solid lies on the right of a -> b. A centre on that
  // side (h < 0), or on the line, leaves by the wall's front normal, as far
  // as its radius past the line: r - h of overlap.
  if (wall.oneSided && len2 > 0.0) {
    const Vec2 front = perpLeft(ab) / std::sqrt(len2);
    const double h = (x - wall.a).dot(front);
    if (h <= 0.0) {
      hit.normal = -front;
      hit.overlap = r - h;
      return true;
    }
  }
  if (dist > 0.0) {
    hit.normal = d / dist;
  } else {
    // Centre exactly on the segment: push out along the segment's right-hand
    // normal (a fixed, documented choice; a point wall falls back to -y).
    hit.normal = len2 > 0.0 ? Vec2(-perpLeft(ab).normalized()) : Vec2(0.0, -1.0);
  }
  hit.overlap = r - dist;
  return true;
}

void findPairsBruteForce(std::span<const Vec2> position, std::span<const double> radius,
                         std::vector<BallPair>& out) {
  out.clear();
  const int n = static_cast<int>(position.size());
  BallPair pair;
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      if (touchBalls(position[a], radius[a], position[b], radius[b], pair)) {
        pair.a = a;
        pair.b = b;
        out.push_back(pair);
      }
    }
  }
}

void BroadPhase::findPairs(std::span<const Vec2> position, std::span<const double> radius,
                           std::vector<BallPair>& out) {
  out.clear();
  const int n = static_cast<int>(position.size());
  if (n < 2) return;

  Vec2 lo = position[0], hi = position[0];
  double maxRadius = 0.0;
  bool finite = true;  // min/max skip NaNs: a NaN position leaves lo and hi finite
  for (int i = 0; i < n; ++i) {
    lo = lo.cwiseMin(position[i]);
    hi = hi.cwiseMax(position[i]);
    maxRadius = std::max(maxRadius, radius[i]);
    finite = finite && position[i].allFinite();
  }
  // Cells one largest diameter wide: touching balls are in the same or a
  // neighbouring cell. A sparse scene would need a huge grid, so the cell
  // count is capped near 4 n by widening the cells.
  // The slop lets touching balls be a hair more than a diameter apart; the
  // cells are widened by more than it so they still land in neighbouring cells.
  double cell = 2.0 * maxRadius * (1.0 + 4.0 * kTouchSlop);
  const Vec2 extent = hi - lo;
  if (!finite || !extent.allFinite() || !(maxRadius > 0.0)) {
    // Positions spread beyond a double's range, or not finite (a diverged
    // run; a NaN cell index would write out of bounds): no grid can be laid
    // over them, and brute force gives the same pairs.
    findPairsBruteForce(position, radius, out);
    return;
  }
  const double maxCells = 4.0 * n + 16.0;
  while ((std::floor(extent.x() / cell) + 1.0) * (std::floor(extent.y() / cell) + 1.0) > maxCells)
    cell *= 2.0;
  const int cols = static_cast<int>(std::floor(extent.x() / cell)) + 1;
  const int rows = static_cast<int>(std::floor(extent.y() / cell)) + 1;
  const double inv = 1.0 / cell;

  // Counting sort of balls into cells; within a cell, ascending index.
  cellStart_.assign(static_cast<std::size_t>(cols) * rows + 1, 0);
  ballCell_.resize(n);
  for (int i = 0; i < n; ++i) {
    const int cx = std::min(cols - 1, static_cast<int>((position[i].x() - lo.x()) * inv));
    const int cy = std::min(rows - 1, static_cast<int>((position[i].y() - lo.y()) * inv));
    ballCell_[i] = cy * cols + cx;
    ++cellStart_[ballCell_[i] + 1];
  }
  for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
  cellBalls_.resize(n);
  cellFill_.assign(cellStart_.begin(), cellStart_.end() - 1);
  for (int i = 0; i < n; ++i) cellBalls_[cellFill_[ballCell_[i]]++] = i;

  BallPair pair;
  for (int a = 0; a < n; ++a) {
    const int cx = ballCell_[a] % cols;
    const int cy = ballCell_[a] / cols;
    for (int y = std::max(0, cy - 1); y <= std::min(rows - 1, cy + 1); ++y) {
      for (int x = std::max(0, cx - 1); x <= std::min(cols - 1, cx + 1); ++x) {
        const int c = y * cols + x;
        for (int k = cellStart_[c]; k < cellStart_[c + 1]; ++k) {
          const int b = cellBalls_[k];
          if (b <= a) continue;
          if (touchBalls(position[a], radius[a], position[b], radius[b], pair)) {
            pair.a = a;
            pair.b = b;
            out.push_back(pair);
          }
        }
      }
    }
  }
  // Same order as brute force, so results never depend on the finder.
  std::sort(out.begin(), out.end(), [](const BallPair& p, const BallPair& q) {
    return p.a != q.a ? p.a < q.a : p.b < q.b;
  });
}

std::size_t BroadPhase::memoryBytes() const {
  return sizeof(int) * (cellStart_.capacity() + cellBalls_.capacity() + cellFill_.capacity() +
                        ballCell_.capacity());
}

void findWallHits(std::span<const Vec2> position, std::span<const double> radius,
                  std::span<const WallDef> walls, std::vector<WallHit>& out) {
  out.clear();
  WallHit hit;
  const int n = static_cast<int>(position.size());
  const int w = static_cast<int>(walls.size());
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < w; ++k) {
      if (touchWall(position[i], radius[i], walls[k], hit)) {
        hit.ball = i;
        hit.wall = k;
        out.push_back(hit);
      }
    }
  }
}

}  // namespace particles
