// The large-scene path's rows (docs/scale.md): the grid, the pair search and
// the rows in strip order, warm-started from the last step's impulses.
#include "particles/scale_solver.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "particles/broad_phase.h"
#include "particles/step_error.h"
#include "scale_common.h"

namespace particles {
namespace {

using scale::kMaxStrips;
using scale::part;

// The same contact test as the broad phase (broad_phase.cpp).
constexpr double kTouchSlop = 1e-9;
// Pairs closer than this fraction of the largest radius (beyond touching)
// become rows too: "speculative" rows that let the two approach by at most
// their gap within the step, so that a contact that closes during the step
// is caught by the velocity solve and then by the overlap removal, with one
// pair search per step.
constexpr double kMarginFraction = 0.2;
// Grid columns per strip, at least: within a strip the rows are solved in
// (a, b) order, which in the cell numbering is bottom-up; wider strips keep
// more of that order. Measured on the pile (docs/scale.md), when rows were
// still in the scene's numbering: 1 column, 12.8 % max overlap at N =
// 10,000; 4, 10.6 %; 8, 8.0 %; 16, 9.5 %.
constexpr int kStripColumns = 8;

// Writes to `out` the numbers of the balls base[begin, end) whose centres
// lie within ra + their radius + margin of xa; returns the new end. `out`
// must have room for every candidate. A function of its own so that the
// loop's values stay in registers (in the pair search's lambda every
// captured value was reloaded after each store).
inline int* nearBalls(const ScaleSolver::CellBall* base, int begin, int end, Vec2 xa, double ra,
                      double margin, int* out) {
  // Without branches: whether a candidate is kept is as good as random, and
  // mispredicted jumps cost more than the arithmetic of the rejected ones.
  for (int k = begin; k < end; ++k) {
    const Vec2 d = base[k].position - xa;
    const double limit = ra + base[k].radius + margin;
    *out = k;
    out += static_cast<int>(d.squaredNorm() <= limit * limit);
  }
  return out;
}

// Whether a ball (centre x, radius grown by the margin) reaches a wall, with
// the hit as touchWall gives it.
inline bool nearWall(const Vec2& x, double grown, const WallDef& wall, WallHit& hit) {
  const Vec2 reach(grown, grown);
  if (scale::wallOutsideBox(x - reach, x + reach, wall)) return false;
  return touchWall(x, grown, wall, hit);
}

// Where a fast pair meets within the step, on the velocities it starts
// with (docs/scale.md, "Rows for fast pairs"): d0 is b's centre from a's,
// w b's velocity relative to a's, touch the sum of the radii. The moment is
// the first touch; for a pair that passes by, the closest approach; for a
// pair still closing at the end of the step, the end (all within [0, dt]).
// `normal` is the line of centres at that moment (for a touch, the contact
// normal of the impact, exact for constant velocities) and `along` the
// centres' distance along it at the start (> touch), so that the row lets
// the pair close by along - touch within the step: a pair that passes by
// is asked for nothing, where a row along the line of centres at the start
// deflected it (at 60 m/s, a ball passing 0.1 m clear of another left at
// 10.9 m/s sideways: ScaleFastPairs.AFastBallPassingAnotherIsNotDeflected).
// The row stays, whatever fastContact says: the solve may set either ball
// moving another way within the step (dropping the pairs that would not
// meet left balls knocked by a landing ball without rows, and the 100,000
// pile with a 192 % overlap at step 300). False for a pair not closing, which
// keeps the line of centres at the start. A head-on pair gets the start's
// normal and distance to the bit (d0 and w parallel to an axis).
inline bool fastContact(const Vec2& d0, const Vec2& w, double touch, double dt, Vec2& normal,
                        double& along) {
  const double dw = d0.dot(w);
  if (!(dw < 0.0)) return false;
  const double ww = w.squaredNorm();
  double t = std::min(-dw / ww, dt);  // the closest approach within the step
  // |d0 + w t| = touch: the first root is > 0, as |d0| > touch and dw < 0.
  const double disc = dw * dw - ww * (d0.squaredNorm() - touch * touch);
  if (disc > 0.0) t = std::min(t, (-dw - std::sqrt(disc)) / ww);
  const Vec2 d = d0 + t * w;
  const double d2 = d.squaredNorm();
  if (!(d2 > 0.0) || !std::isfinite(d2)) return false;
  normal = d / std::sqrt(d2);
  along = d0.dot(normal);
  return along > touch;
}

// The longer search of a fast ball a (reach `ea` beyond touching, > 0): the
// balls in the cells within `k` of its cell (cx, cy) that it may reach within
// the step and that the plain search did not pair with it, in cell order.
// Each pair once: from the ball of the larger reach, or of the lower number
// when both reach as far. Calls f(b) for each.
template <class F>
inline void fastPartners(const ScaleSolver::CellBall* cells, const int* cellStart,
                         const double* reach, int cols, int rows, int a, int cx, int cy, int k,
                         double margin, F&& f) {
  const Vec2 xa = cells[a].position;
  const double ra = cells[a].radius, ea = reach[a];
  const int x0 = std::max(0, cx - k), x1 = std::min(cols - 1, cx + k);
  for (int y = std::max(0, cy - k); y <= std::min(rows - 1, cy + k); ++y) {
    const std::size_t first = static_cast<std::size_t>(y) * static_cast<std::size_t>(cols);
    const int from = cellStart[first + static_cast<std::size_t>(x0)];
    const int to = cellStart[first + static_cast<std::size_t>(x1) + 1];
    for (int b = from; b < to; ++b) {
      const double eb = reach[b];
      if (b == a || eb > ea || (eb == ea && b < a)) continue;
      const double d2 = (cells[b].position - xa).squaredNorm();
      const double touch = ra + cells[b].radius;
      // The plain search's test to the bit (nearBalls: the same sum and
      // square from either ball): its pairs are not made twice.
      const double near = touch + margin;
      const double far = touch + ea;
      if (d2 <= near * near || d2 > far * far) continue;
      f(b);
    }
  }
}

// A row's masses and targets, from its bodies (r.a, r.b: their places in
// `body`; sceneA, sceneB: their scene indices, sceneB unused for a wall),
// normal and reach, the distance of the centres (or of the centre from the
// wall), the mixed material and the scene's forced velocities (`forces`:
// whether they differ between balls; when every ball got the same push, as
// from gravity alone, no ball pair's relative velocity changed).
// Returns the row's bounce (ScaleSolver::bounce_).
inline double fillRow(const ScaleSolver::Motion* body, std::size_t sceneA, std::size_t sceneB,
                      const ScaleBodies& s, bool forces, const ContactMaterial& m, double reach,
                      double dist, ScaleSolver::Row& r) {
  const ScaleSolver::Motion& a = body[r.a];
  const ScaleSolver::Motion* b = r.b >= 0 ? &body[r.b] : nullptr;
  const double invA = a.invMass, invB = b ? b->invMass : 0.0;
  r.massN = 1.0 / (invA + invB);
  r.friction = m.friction;
  if (m.friction > 0.0) {
    const double jb = b ? b->radius * b->radius * b->invInertia : 0.0;
    r.massT = 1.0 / (invA + invB + a.radius * a.radius * a.invInertia + jb);
  }
  // The approach the bodies brought into the step: what this step's
  // forces added is cancelled, not bounced (docs/physics.md).
  const Vec2 vb = b ? b->velocity : Vec2::Zero();
  const Vec2 n = r.normal();
  const double gn = (vb - a.velocity).dot(n);
  double forced = 0.0;
  // A wall got no push: a ball's own push is relative to it.
  if (!s.forcedVelocity.empty() && (!b || forces)) {
    const Vec2 fb = b ? s.forcedVelocity[sceneB] : Vec2::Zero();
    forced = (fb - s.forcedVelocity[sceneA]).dot(n);
  }
  const double brought = gn - forced;
  double bounce = 0.0;
  if (dist > reach * (1.0 + kTouchSlop)) {
    // Apart: may approach by at most the gap within the step. If the
    // approach closes the gap, the bodies collide within this step, and
    // the restitution pass gives them their bounce: without it every
    // impact caught early would be perfectly inelastic (an elastic gas
    // of 1,000 balls lost 10 % of its energy in 0.25 s).
    const double gap = dist - reach;
    r.target = -gap / s.dt;
    if (brought * s.dt < -gap) bounce = -m.restitution * brought;
  } else {
    // Touching: bounce the approach brought into the step.
    r.target = brought < 0.0 ? -m.restitution * brought : 0.0;
  }
  return bounce;
}

}  // namespace

// The grid: cells as wide as the largest diameter plus the margin, balls
// counting-sorted into them, then sorted within each cell. The threads share
// every pass over the balls and the cells (measured serial, the grid was 3.4 %
// of a 100,000-ball step's samples on two threads, all of it on the critical
// path). The result does not depend on the thread count: bounds are minima
// and maxima, and the order within a cell is decided by the sort alone.
ScaleSolver::Grid ScaleSolver::buildGrid(const ScaleBodies& s, ThreadPool& pool) {
  const std::size_t n = s.position.size();
  const int threads = pool.size();
  // Each thread's bounds on a cache line of its own.
  struct alignas(64) Bounds {
    Vec2 lo{0.0, 0.0}, hi{0.0, 0.0};
    Vec2 vlo{0.0, 0.0}, vhi{0.0, 0.0};  // velocities (m/s)
    double maxRadius = 0.0;
    double minRadius = INFINITY;
    bool finite = true;
    bool empty = true;
  };
  std::vector<Bounds> bounds(static_cast<std::size_t>(threads));
  pool.run([&](int t) {
    const auto [b, e] = part(n, t, threads);
    Bounds& mine = bounds[static_cast<std::size_t>(t)];
    if (b == e) return;
    mine.empty = false;
    mine.lo = mine.hi = s.position[b];
    mine.vlo = mine.vhi = s.velocity[b];
    for (std::size_t i = b; i < e; ++i) {
      mine.lo = mine.lo.cwiseMin(s.position[i]);
      mine.hi = mine.hi.cwiseMax(s.position[i]);
      mine.vlo = mine.vlo.cwiseMin(s.velocity[i]);
      mine.vhi = mine.vhi.cwiseMax(s.velocity[i]);
      mine.maxRadius = std::max(mine.maxRadius, s.radius[i]);
      mine.minRadius = std::min(mine.minRadius, s.radius[i]);
      mine.finite = mine.finite && s.position[i].allFinite();
    }
  });
  Vec2 lo = s.position[0], hi = s.position[0];
  Vec2 vlo = s.velocity[0], vhi = s.velocity[0];
  double maxRadius = 0.0, minRadius = INFINITY;
  bool finite = true;
  for (const Bounds& b : bounds) {
    if (b.empty) continue;
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
    vlo = vlo.cwiseMin(b.vlo);
    vhi = vhi.cwiseMax(b.vhi);
    maxRadius = std::max(maxRadius, b.maxRadius);
    minRadius = std::min(minRadius, b.minRadius);
    finite = finite && b.finite;
  }
  const double margin = kMarginFraction * maxRadius;
  double cell = (2.0 * maxRadius + margin) * (1.0 + 4.0 * kTouchSlop);
  const Vec2 extent = hi - lo;
  int cols = 1, rows = 1;
  // A diverged state (non-finite positions) gets a single cell: no NaN is
  // ever turned into an index, and NaN distances make no rows.
  if (finite && extent.allFinite() && maxRadius > 0.0) {
    const double maxCells = 4.0 * static_cast<double>(n) + 16.0;
    while ((std::floor(extent.x() / cell) + 1.0) * (std::floor(extent.y() / cell) + 1.0) > maxCells)
      cell *= 2.0;
    cols = static_cast<int>(std::floor(extent.x() / cell)) + 1;
    rows = static_cast<int>(std::floor(extent.y() / cell)) + 1;
  } else {
    finite = false;
  }
  const double inv = 1.0 / cell;
  const std::size_t cells = static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows);
  cellStart_.resize(cells + 1);
  cellCount_.resize(cells * static_cast<std::size_t>(threads));
  ballCell_.resize(n);
  // The balls in cell order: the solver's numbering for this step (the
  // last step's is kept for the warm start).
  std::swap(numberOf_, lastNumberOf_);
  numberOf_.resize(n);
  cellBalls_.resize(n);
  cellOf_.resize(n);
  pool.run([&](int t) {
    const auto [b, e] = part(n, t, threads);
    int* count = cellCount_.data() + static_cast<std::size_t>(t) * cells;
    std::fill(count, count + cells, 0);
    for (std::size_t i = b; i < e; ++i) {
      int c = 0;
      if (finite) {
        const int cx = std::min(cols - 1, static_cast<int>((s.position[i].x() - lo.x()) * inv));
        const int cy = std::min(rows - 1, static_cast<int>((s.position[i].y() - lo.y()) * inv));
        c = cy * cols + cx;
      }
      ballCell_[i] = c;
      ++count[c];
    }
    pool.sync();
    // Where each thread's balls of a cell go.
    if (t == 0) scale::placeByBucket(cellCount_.data(), cells, cells, threads, cellStart_.data());
    pool.sync();
    for (std::size_t i = b; i < e; ++i) {
      const int c = ballCell_[i];
      const int k = count[c]++;
      cellBalls_[static_cast<std::size_t>(k)] = {s.position[i], s.radius[i], static_cast<int>(i)};
      cellOf_[static_cast<std::size_t>(k)] = c;
    }
    pool.sync();
    // Within a cell, bottom-up too (by y, then x; the scene's index only
    // for balls at the same point): then the numbering, and with it every
    // result, is the scene's numbering permuted, whatever order the scene
    // lists its balls in (and whichever thread placed them). A cell holds
    // one or two balls: insertion sort.
    const auto below = [](const CellBall& p, const CellBall& q) {
      if (p.position.y() != q.position.y()) return p.position.y() < q.position.y();
      if (p.position.x() != q.position.x()) return p.position.x() < q.position.x();
      return p.index < q.index;
    };
    const auto [c0, c1] = part(cells, t, threads);
    for (std::size_t c = c0; c < c1; ++c)
      for (int k = cellStart_[c] + 1; k < cellStart_[c + 1]; ++k)
        for (int j = k; j > cellStart_[c] && below(cellBalls_[static_cast<std::size_t>(j)],
                                                   cellBalls_[static_cast<std::size_t>(j) - 1]);
             --j)
          std::swap(cellBalls_[static_cast<std::size_t>(j)],
                    cellBalls_[static_cast<std::size_t>(j) - 1]);
    pool.sync();
    for (std::size_t k = b; k < e; ++k)
      numberOf_[static_cast<std::size_t>(cellBalls_[k].index)] = static_cast<int>(k);
  });
  // No two balls close faster than the span of the velocities: when that
  // stays within the margin a step (a pile at rest), no ball needs the
  // longer search of fast pairs, and nothing of it runs. A NaN compares false.
  const double span = (vhi - vlo).squaredNorm() * (s.dt * s.dt);
  const bool fast = finite && span > margin * margin;
  return {cols, rows, margin, cell, maxRadius, minRadius, fast};
}

// Rows for fast pairs (docs/scale.md, "Rows for fast pairs"): the reach
// beyond touching of each ball's longer search. Two balls close on each other
// no faster than their velocities differ, and a ball's velocity differs from
// any other within k cells of it by at most its distance from the box of the
// velocities in those cells: each cell's box, grown along its grid row, then
// per ball across the grid rows. A ball whose distance, times dt, exceeds
// the margin searches that far (up to k cells), the others not at all. Run
// by every thread t of the pool (three barriers).
void ScaleSolver::findFastReach(const ScaleBodies& s, const Grid& grid, int k, int t,
                                ThreadPool& pool) {
  const int cols = grid.cols, rows = grid.rows, threads = pool.size();
  const std::size_t cells = static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows);
  constexpr float kInf = std::numeric_limits<float>::infinity();
  const auto grow = [](VelocityBox& box, const VelocityBox& other) {
    box.loX = std::min(box.loX, other.loX);
    box.loY = std::min(box.loY, other.loY);
    box.hiX = std::max(box.hiX, other.hiX);
    box.hiY = std::max(box.hiY, other.hiY);
  };
  const auto [c0, c1] = part(cells, t, threads);
  for (std::size_t c = c0; c < c1; ++c) {
    VelocityBox box{kInf, kInf, -kInf, -kInf};
    for (int j = cellStart_[c]; j < cellStart_[c + 1]; ++j) {
      const Vec2& v =
          s.velocity[static_cast<std::size_t>(cellBalls_[static_cast<std::size_t>(j)].index)];
      const float vx = static_cast<float>(v.x()), vy = static_cast<float>(v.y());
      grow(box, {vx, vy, vx, vy});
    }
    cellBox_[c] = box;
  }
  pool.sync();
  for (std::size_t c = c0; c < c1; ++c) {
    const int x = static_cast<int>(c % static_cast<std::size_t>(cols));
    const std::size_t first = c - static_cast<std::size_t>(x);
    VelocityBox box{kInf, kInf, -kInf, -kInf};
    for (int u = std::max(0, x - k); u <= std::min(cols - 1, x + k); ++u)
      grow(box, cellBox_[first + static_cast<std::size_t>(u)]);
    rowBox_[c] = box;
  }
  pool.sync();
  const auto [b, e] = part(s.position.size(), t, threads);
  const double margin = grid.margin;
  // Partners beyond k cells are not in the box: the reach stops short of them.
  const double cap = k * grid.cell - grid.maxRadius;
  for (std::size_t j = b; j < e; ++j) {
    const int c = cellOf_[j], cx = c % cols, cy = c / cols;
    VelocityBox box{kInf, kInf, -kInf, -kInf};
    for (int y = std::max(0, cy - k); y <= std::min(rows - 1, cy + k); ++y)
      grow(box, rowBox_[static_cast<std::size_t>(y) * static_cast<std::size_t>(cols) +
                        static_cast<std::size_t>(cx)]);
    const Vec2& v = s.velocity[static_cast<std::size_t>(cellBalls_[j].index)];
    const double dx = std::max(v.x() - box.loX, box.hiX - v.x());
    const double dy = std::max(v.y() - box.loY, box.hiY - v.y());
    const double step2 = (dx * dx + dy * dy) * (s.dt * s.dt);
    double reach = 0.0;
    if (step2 > margin * margin) reach = std::min(std::sqrt(step2), cap - cellBalls_[j].radius);
    fastReach_[j] = reach > margin ? reach : 0.0;
  }
  pool.sync();
}

void ScaleSolver::findRows(const ScaleBodies& s, ThreadPool& pool, int fastCells, int bandRows,
                           bool soft) {
  const std::size_t n = s.position.size();
  // Plain names, not a structured binding: the lambdas below use them, and
  // clang before 16 (Debian 12 has 14) cannot capture a structured binding.
  const Grid grid = buildGrid(s, pool);
  const int cols = grid.cols, rows = grid.rows;
  const double margin = grid.margin;
  // The most rows this step may make (scale::kMaxRowsPerBall a ball for
  // equal radii). Disks that do not overlap, of radius at least rmin, whose
  // centres lie within reach of a ball (ra + rb + margin <= 2.2 rmax) are
  // at most (2.2 rmax / rmin + 1)^2 <= 10.24 (rmax / rmin)^2: the bound
  // grows with the square of the radius spread, so that a boulder in fine
  // sand, whose margin spans many grains, is stepped as before.
  const double spread =
      grid.minRadius > 0.0 && std::isfinite(grid.maxRadius) ? grid.maxRadius / grid.minRadius : 1.0;
  const double rowsPerBall =
      static_cast<double>(scale::kMaxRowsPerBall) * std::max(1.0, spread * spread);
  const double rowLimit = rowsPerBall * static_cast<double>(n);
  const std::size_t rowBudget = rowLimit < 1e18 ? static_cast<std::size_t>(rowLimit)
                                                : std::numeric_limits<std::size_t>::max() / 2;
  // The pairs every thread has found so far (8 bytes each).
  const auto linksFound = [&] {
    std::size_t found = 0;
    for (const ThreadLinks& f : found_) found += f.links.size();
    return found;
  };
  // The last step's impulses can be matched only if it had the same balls
  // (reset() empties its numbering).
  const bool warm = lastNumberOf_.size() == n;

  // Rows are split into vertical strips of kStripColumns grid columns, so a
  // row joins balls of the same or of neighbouring strips; a row belongs to
  // the strip of its left ball. Rows of two even strips (or of two odd
  // strips) then share no ball: all even strips can be solved at once, each in
  // (a, b) order (Gauss-Seidel), then all odd strips. The strips depend on the
  // positions only, never on the thread count, so the result is the same for
  // any count.
  // From 4 strips on, a multiple of 4 (wider strips instead of one more):
  // then each parity splits evenly between two threads, as this machine has
  // two cores. At N = 10,000 (14 strips before, so 4 against 3 of a parity)
  // 12 strips made two threads 12 % faster in three A/B pairs, with no loss
  // of accuracy over 8 seeds (docs/scale.md, "Cell order"). One short of a
  // multiple of 4 rounds up instead (11 -> 12, strips one column narrower
  // than kStripColumns): rounding down left the polydisperse 10,000 pile 8
  // strips, 2 of a parity per thread, and two threads gained nothing (2.08
  // M disk-steps/s against 3.53 M with 12, median of 8 seeds; docs/scale.md,
  // "Strip count"). The count depends on the grid only, never on the
  // thread count.
  int strips = std::clamp(cols / kStripColumns, 1, kMaxStrips);
  if (strips >= 4) strips = std::min(kMaxStrips, (strips + 1) / 4 * 4);
  const int threads = pool.size();
  // A row's balls must lie in the same or neighbouring strips: the longer
  // search of fast balls reaches no further than a strip is wide (at least
  // cols / strips columns).
  int fast = grid.fast ? std::max(0, fastCells) : 0;
  if (strips > 1) fast = std::min(fast, cols / strips);
  if (fast > 0) {
    const std::size_t cellCount = static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows);
    cellBox_.resize(cellCount);
    rowBox_.resize(cellCount);
    fastReach_.resize(n);
  }
  const std::size_t width = static_cast<std::size_t>(strips) + 1;
  // Each thread's counters on cache lines of their own (16 ints = 64 bytes).
  const std::size_t stride = (width + 15) / 16 * 16;
  // The rows are counted by strip and band (docs/scale.md, "Bands"): a row
  // lies in the band of its ball a, the lower-numbered (lower) one.
  const int band = std::max(0, bandRows);
  const int bands = band > 0 ? (rows + band - 1) / band : 1;
  const std::size_t blocks = static_cast<std::size_t>(strips) * static_cast<std::size_t>(bands);
  const std::size_t blockStride = (blocks + 1 + 15) / 16 * 16;
  // Each grid column's strip and each grid row's band, looked up per ball
  // once (bandOf_) instead of two integer divisions per row found and made.
  stripOfColumn_.resize(static_cast<std::size_t>(cols));
  for (int x = 0; x < cols; ++x)
    // Whole grid columns per strip: neighbours are at most one column apart.
    stripOfColumn_[static_cast<std::size_t>(x)] = x * strips / cols;
  bandOfRow_.resize(static_cast<std::size_t>(rows));
  for (int y = 0; y < rows; ++y) bandOfRow_[static_cast<std::size_t>(y)] = band > 0 ? y / band : 0;
  const auto blockOf = [&](int strip, std::size_t a) {
    return static_cast<std::size_t>(strip) * static_cast<std::size_t>(bands) +
           static_cast<std::size_t>(bandOf_[a]);
  };
  strips_ = strips;
  bands_ = bands;
  // A plain row's ball b lies in a's grid row or the one above; a fast
  // pair's up to `fast` grid rows above or below (fastPartners).
  bandReach_ = band > 0 ? (std::max(1, fast) + band - 1) / band + (fast + band - 1) / band : 1;
  stripOf_.resize(n);
  bandOf_.resize(n);
  slotOf_.resize(n);
  slotCount_.assign(static_cast<std::size_t>(threads) * stride, 0);
  lastOf_.resize(n);
  motion_.resize(n);
  invMass_.resize(n);
  blockCount_.assign(static_cast<std::size_t>(threads) * blockStride, 0);
  blockStart_.assign(blocks + 1, 0);
  if (soft) {
    ballBlockCount_.assign(static_cast<std::size_t>(threads) * blockStride, 0);
    ballBlockStart_.assign(blocks + 1, 0);
  }
  found_.resize(static_cast<std::size_t>(threads));
  linkStart_.assign(static_cast<std::size_t>(threads) + 1, 0);
  const CellBall* cells = cellBalls_.data();
  Motion* body = motion_.data();
  // Whether every ball has the first ball's material, and got the first
  // ball's forced velocity this step (each thread's answer on a cache line
  // of its own). The usual large scene (one material, gravity alone) then
  // mixes its materials once per step instead of once per row, and reads no
  // ball's material or forced velocity per row: both lie in the scene's
  // numbering, one scattered load per ball of a row. Same bits: the mix of
  // equal inputs is the same, and equal pushes change no relative velocity.
  struct alignas(64) Same {
    bool material = true;
    bool forced = true;
  };
  std::vector<Same> same(static_cast<std::size_t>(threads));
  const bool anyForces = !s.forcedVelocity.empty();
  // The first ball's material mixed with itself and with each wall's, once
  // for all threads: the rows' materials if every ball has it.
  const ContactMaterial ballMix = mixMaterials(s.material[0], s.material[0]);
  std::vector<ContactMaterial> wallMix(s.walls.size());
  for (std::size_t w = 0; w < s.walls.size(); ++w)
    wallMix[w] = mixMaterials(s.material[0], s.wallMaterial[w]);
  pool.run([&](int t) {
    const auto [begin, end] = part(n, t, threads);
    // In locals, with & rather than &&: a store to `same` every ball and a
    // branch every comparison made this loop 1.2 % of the 100,000 pile's
    // samples.
    const ContactMaterial first = s.material[0];
    bool material = true, forced = true;
    for (std::size_t i = begin; i < end; ++i)
      material &= (s.material[i].restitution == first.restitution) &
                  (s.material[i].friction == first.friction);
    if (anyForces) {
      const Vec2 push = s.forcedVelocity[0];
      for (std::size_t i = begin; i < end; ++i)
        forced &= (s.forcedVelocity[i].x() == push.x()) & (s.forcedVelocity[i].y() == push.y());
    }
    same[static_cast<std::size_t>(t)] = {material, forced};
    int* slots = slotCount_.data() + static_cast<std::size_t>(t) * stride;
    int* ballsIn =
        soft ? ballBlockCount_.data() + static_cast<std::size_t>(t) * blockStride : nullptr;
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t i = static_cast<std::size_t>(cells[k].index);
      const int cy = cellOf_[k] / cols;
      stripOf_[k] = stripOfColumn_[static_cast<std::size_t>(cellOf_[k] - cy * cols)];
      bandOf_[k] = bandOfRow_[static_cast<std::size_t>(cy)];
      ++slots[stripOf_[k]];
      if (soft) ++ballsIn[blockOf(stripOf_[k], k)];
      invMass_[k] = s.invMass[i];
      lastOf_[k] = warm ? lastNumberOf_[i] : -1;
    }
    pool.sync();
    // Where each thread's balls of a strip go in motion_.
    if (t == 0) {
      scale::placeByBucket(slotCount_.data(), stride, static_cast<std::size_t>(strips), threads,
                           nullptr);
      // The soft step's ball passes go block by block, as the rows do. A
      // strip's balls lie in motion_ thread by thread, each thread's in cell
      // order, and cell order runs bottom-up: a strip's balls lie there band
      // by band, and each block's balls are one run.
      if (soft)
        scale::placeByBucket(ballBlockCount_.data(), blockStride, blocks, threads,
                             ballBlockStart_.data());
    }
    pool.sync();
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t i = static_cast<std::size_t>(cells[k].index);
      const int slot = slots[stripOf_[k]]++;
      slotOf_[k] = slot;
      // Each ball's velocity and mass properties in one place: a row touches
      // two of them.
      body[slot] = {s.velocity[i], s.angularVelocity[i], s.invMass[i], s.invInertia[i],
                    s.radius[i]};
    }
    pool.sync();
    if (fast > 0) findFastReach(s, grid, fast, t, pool);
    bool mixOnce = true, forces = false;
    for (const Same& u : same) {
      mixOnce = mixOnce && u.material;
      forces = forces || !u.forced;
    }

    // First the pairs only (8 bytes each), in (a, b) order, counted per
    // strip; then, once every thread's counts are known, each row is made in
    // its place in strip order. Making the (then 96-byte) rows first and moving them
    // into strip order afterwards cost a tenth of the step at N = 100,000.
    std::vector<Link>& links = found_[static_cast<std::size_t>(t)].links;
    links.clear();
    int* count = blockCount_.data() + static_cast<std::size_t>(t) * blockStride;
    std::vector<int> partners;  // this ball's, in increasing order
    // A thread that alone found more rows than all threads may have stops:
    // the step fails whatever the thread count (below).
    for (std::size_t ia = begin; ia < end && links.size() <= rowBudget; ++ia) {
      const int a = static_cast<int>(ia);
      const Vec2 xa = cells[ia].position;
      const double ra = cells[ia].radius;
      const int sa = stripOf_[ia];
      const int cx = cellOf_[ia] % cols, cy = cellOf_[ia] / cols;
      const std::size_t x0 = static_cast<std::size_t>(std::max(0, cx - 1));
      const std::size_t x1 = static_cast<std::size_t>(std::min(cols - 1, cx + 1));
      // The partners numbered after a: in its own grid row, the rest of its
      // cell and the cell to its right (the cell to its left comes before
      // it); in the grid row above, the three cells (the row below comes
      // before it). Both runs are in increasing order, the first before the
      // second: the partners need no sorting.
      const std::size_t here = static_cast<std::size_t>(cy) * static_cast<std::size_t>(cols);
      std::array<std::pair<int, int>, 2> runs{};
      runs[0] = {a + 1, cellStart_[here + x1 + 1]};
      if (cy + 1 < rows) {
        const std::size_t above = here + static_cast<std::size_t>(cols);
        runs[1] = {cellStart_[above + x0], cellStart_[above + x1 + 1]};
      }
      partners.resize(static_cast<std::size_t>(runs[0].second - runs[0].first) +
                      static_cast<std::size_t>(runs[1].second - runs[1].first));
      int* near = partners.data();
      for (const auto& [from, to] : runs) near = nearBalls(cells, from, to, xa, ra, margin, near);
      partners.resize(static_cast<std::size_t>(near - partners.data()));
      for (const int b : partners) {
        links.push_back({a, b});
        ++count[blockOf(std::min(sa, stripOf_[static_cast<std::size_t>(b)]), ia)];
      }
      for (std::size_t w = 0; w < s.walls.size(); ++w) {
        WallHit hit;
        if (!nearWall(xa, ra + margin, s.walls[w], hit)) continue;
        links.push_back({a, -1 - static_cast<int>(w)});
        ++count[blockOf(sa, ia)];
      }
      // A fast ball's speculative rows with the balls beyond the margin it
      // may reach within the step; a ball numbered before a comes after a's
      // own partners here, so a thread's links stay in order of their first
      // ball (the warm start of such a row is kept under a, where the next
      // step, which looks under the lower number, does not find it).
      if (fast > 0 && fastReach_[ia] > 0.0)
        fastPartners(cells, cellStart_.data(), fastReach_.data(), cols, rows, a, cx, cy, fast,
                     margin, [&](int b) {
                       links.push_back({a, b});
                       ++count[blockOf(std::min(sa, stripOf_[static_cast<std::size_t>(b)]), ia)];
                     });
    }
    pool.sync();
    if (linksFound() > rowBudget) return;  // every thread returns here: findRows throws
    if (t == 0) {
      for (int u = 0; u < threads; ++u)
        linkStart_[static_cast<std::size_t>(u) + 1] =
            linkStart_[static_cast<std::size_t>(u)] +
            found_[static_cast<std::size_t>(u)].links.size();
      slot_.resize(linkStart_.back());
      rows_.resize(linkStart_.back());
      pairs_.resize(linkStart_.back());
      bounce_.resize(linkStart_.back());
      if (soft) separation_.resize(linkStart_.back());
      // Where each thread's rows of each strip and band start, so that a
      // strip's rows are in (a, b) order (the bands of a strip follow each
      // other, since a's band grows with a).
      scale::placeByBucket(blockCount_.data(), blockStride, blocks, threads, blockStart_.data());
    }
    pool.sync();

    int* slot = slot_.data() + linkStart_[static_cast<std::size_t>(t)];
    for (std::size_t k = 0; k < links.size(); ++k) {
      const int a = links[k].a, b = links[k].b;
      const CellBall& ca = cells[a];
      const std::size_t ia = static_cast<std::size_t>(ca.index);
      Row r;
      r.a = slotOf_[static_cast<std::size_t>(a)];
      r.b = b >= 0 ? slotOf_[static_cast<std::size_t>(b)] : b;
      std::size_t sceneB = 0;
      double dist = 0.0, reach = 0.0;
      ContactMaterial m;
      Vec2 normal;
      if (b >= 0) {
        const CellBall& cb = cells[b];
        sceneB = static_cast<std::size_t>(cb.index);
        const Vec2 d = cb.position - ca.position;
        reach = ca.radius + cb.radius;
        // A pair apart (beyond touching) whose relative motion within the
        // step exceeds the margin, from the plain or the longer search, gets
        // its row where fastContact says the pair meets; along the line of
        // centres at the start, a ball passing 0.02 m clear of another at
        // 60 m/s left at 11.3 m/s sideways. Any other pair (touching, slow,
        // or not closing): the line of centres at the start.
        const double d2 = d.squaredNorm();
        const Vec2 w = body[r.b].velocity - body[r.a].velocity;  // s.velocity's copies
        const bool swept = d2 > reach * reach && w.squaredNorm() * (s.dt * s.dt) > margin * margin;
        if (!swept || !fastContact(d, w, reach, s.dt, normal, dist)) {
          dist = std::sqrt(d2);
          normal = dist > 0.0 ? Vec2(d / dist) : Vec2(1.0, 0.0);
        }
        m = mixOnce ? ballMix
                    : mixMaterials(s.material[ia], s.material[static_cast<std::size_t>(cb.index)]);
      } else {
        const std::size_t w = static_cast<std::size_t>(-1 - b);
        WallHit hit;
        nearWall(ca.position, ca.radius + margin, s.walls[w], hit);
        reach = ca.radius;
        dist = ca.radius + margin - hit.overlap;
        normal = hit.normal;
        m = mixOnce ? wallMix[w] : mixMaterials(s.material[ia], s.wallMaterial[w]);
      }
      r.nx = normal.x();
      r.ny = normal.y();
      const double bounce = fillRow(body, ia, sceneB, s, forces, m, reach, dist, r);
      // Warm start from the last step's row of the same two bodies, if any.
      // The impulses do not depend on which ball is a: swapping a and b
      // turns n and tau (= perp n) around and P on b into P on a.
      const int la = lastOf_[static_cast<std::size_t>(a)];
      const int lb = b >= 0 ? lastOf_[static_cast<std::size_t>(b)] : static_cast<int>(n) + (-1 - b);
      if (la >= 0 && lb >= 0) {
        const std::size_t lo = static_cast<std::size_t>(b >= 0 ? std::min(la, lb) : la);
        const int other = b >= 0 ? std::max(la, lb) : lb;
        for (int j = lastStart_[lo]; j < lastStart_[lo + 1]; ++j) {
          if (lastOther_[static_cast<std::size_t>(j)] != other) continue;
          r.lambdaN = lastN_[static_cast<std::size_t>(j)];
          r.lambdaT = lastT_[static_cast<std::size_t>(j)];
          break;
        }
      }
      const int st = b >= 0 ? std::min(stripOf_[static_cast<std::size_t>(a)],
                                       stripOf_[static_cast<std::size_t>(b)])
                            : stripOf_[static_cast<std::size_t>(a)];
      const int pos = count[blockOf(st, static_cast<std::size_t>(a))]++;
      rows_[static_cast<std::size_t>(pos)] = r;
      pairs_[static_cast<std::size_t>(pos)] = {a, b, reach};
      bounce_[static_cast<std::size_t>(pos)] = bounce;
      if (soft) separation_[static_cast<std::size_t>(pos)] = dist - reach;
      slot[k] = pos;
    }
  });
  if (const std::size_t found = linksFound(); found > rowBudget) {
    // Before the rows are made, so memory stays bounded: links are 8 bytes,
    // the rows and their pairs 96 more each.
    for (ThreadLinks& f : found_) std::vector<Link>().swap(f.links);
    throw StepError("large-scene step: more than " + std::to_string(std::llround(rowsPerBall)) +
                    " contact rows a ball (" + std::to_string(found) + " or more for " +
                    std::to_string(n) +
                    " balls): the balls are heaped into each other far beyond touching, as "
                    "after a blow-up; stopped before running out of memory");
  }
}

}  // namespace particles
