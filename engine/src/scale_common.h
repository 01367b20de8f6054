// What the two halves of the large-scene path (scale_rows.cpp builds the
// rows, scale_solver.cpp solves them) share.
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>

#include "particles/scale_solver.h"
#include "particles/scene.h"
#include "particles/types.h"

namespace particles::scale {

// Upper bound on the strips of the parallel solve (even: a fixed number, so
// that no result depends on the thread count).
constexpr int kMaxStrips = 32;

// Contact rows a step may make, per ball of the scene (on average), when
// all radii are equal; findRows scales it by (largest / smallest radius)^2.
// The benchmark piles make at most 2.34 (10,000 disks, mono- and
// polydisperse, any of 600 steps: a touching pair is one row and a settled
// disk touches about 4.7 others), and equal disks that do not overlap can
// have at most 10.24 within reach; a ball can be within reach of far more
// only by overlapping them deeply. A state past the bound is not stepped
// (StepError): at 100,000 balls with the support sweep off, the pile's balls
// piled into each other and the rows took all 24 GiB of the machine before
// the bound (docs/scale.md, "A state that cannot be stepped"). Bounds the
// rows' memory to about 6 KiB a ball (equal radii).
constexpr std::size_t kMaxRowsPerBall = 64;

// Items [begin, end) of part t of T: a split by index only, never by timing.
inline std::pair<std::size_t, std::size_t> part(std::size_t n, int t, int threads) {
  const std::size_t tt = static_cast<std::size_t>(t), tn = static_cast<std::size_t>(threads);
  return {n * tt / tn, n * (tt + 1) / tn};
}

// Turns counts[u * stride + k], thread u's items in bucket k, into the place
// of thread u's first item of bucket k: bucket by bucket, thread by thread,
// so that each bucket keeps the items' order (thread u has the u-th range of
// them). When `start` is not null, also writes each bucket's first place to
// start[k] and the total to start[buckets]. The threads' shared counting
// sorts (cells, strips of balls, strips of rows) all place this way.
inline void placeByBucket(int* counts, std::size_t stride, std::size_t buckets, int threads,
                          int* start) {
  int at = 0;
  for (std::size_t k = 0; k < buckets; ++k) {
    if (start) start[k] = at;
    for (int u = 0; u < threads; ++u) {
      int& c = counts[static_cast<std::size_t>(u) * stride + k];
      const int here = c;
      c = at;
      at += here;
    }
  }
  if (start) start[buckets] = at;
}

// Whether the wall's segment lies wholly outside the box [lo, hi] (m): a
// ball whose reach stays inside the box cannot touch the wall. Most balls of
// a large scene are far from every wall, and this skips the segment
// distance. A NaN corner compares false: not outside.
inline bool wallOutsideBox(const Vec2& lo, const Vec2& hi, const WallDef& wall) {
  return hi.x() < std::min(wall.a.x(), wall.b.x()) || lo.x() > std::max(wall.a.x(), wall.b.x()) ||
         hi.y() < std::min(wall.a.y(), wall.b.y()) || lo.y() > std::max(wall.a.y(), wall.b.y());
}

// Applies P = dn n + dt tau to the two bodies of a row (b < 0: a wall, which
// takes nothing). Signs as in contact_impulse_impl.h: b gets +P, a gets -P,
// and both spins change by -r dt / J.
inline void applyRow(ScaleSolver::Motion* m, const ScaleSolver::Row& r, double dn, double dt) {
  const Vec2 n = r.normal();
  const Vec2 p = dn * n + dt * perpLeft(n);
  ScaleSolver::Motion& a = m[r.a];
  a.velocity -= a.invMass * p;
  a.angularVelocity -= a.radius * dt * a.invInertia;
  if (r.b >= 0) {
    ScaleSolver::Motion& b = m[r.b];
    b.velocity += b.invMass * p;
    b.angularVelocity -= b.radius * dt * b.invInertia;
  }
}

}  // namespace particles::scale
