// The large-scene path's rows (docs/scale.md): the grid, the pair search and
// the rows in strip order, warm-started from the last step's impulses.
#include "particles/scale_solver.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "particles/broad_phase.h"
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
// key order, which for a pile numbered row by row from the bottom is close
// to bottom-up; wider strips keep more of that order. Measured on the pile
// (docs/scale.md): 1 column, 12.8 % max overlap at N = 10,000; 4, 10.6 %;
// 8, 8.0 %; 16, 9.5 %.
constexpr int kStripColumns = 8;

// Writes to `out` the balls of [k, stop) after ball a (by index) whose
// centres lie within ra + their radius + margin of xa; returns the new end.
// `out` must have room for every candidate. A function of its own so that the
// loop's values stay in registers (in the pair search's lambda every captured
// value was reloaded after each store).
inline int* nearBalls(const ScaleSolver::CellBall* k, const ScaleSolver::CellBall* stop, int a,
                      Vec2 xa, double ra, double margin, int* out) {
  // Without branches: whether a candidate is kept is as good as random
  // (half of them come before a), and mispredicted jumps cost more than the
  // arithmetic of the rejected ones.
  for (; k != stop; ++k) {
    const Vec2 d = k->position - xa;
    const double limit = ra + k->radius + margin;
    *out = k->index;
    out += static_cast<int>(k->index > a) & static_cast<int>(d.squaredNorm() <= limit * limit);
  }
  return out;
}

// Whether a ball (centre x, radius grown by the margin) reaches a wall, with
// the hit as touchWall gives it. A ball outside the wall's box grown by its
// reach cannot touch it: most balls of a pile skip the segment distance.
inline bool nearWall(const Vec2& x, double grown, const WallDef& wall, WallHit& hit) {
  if (x.x() + grown < std::min(wall.a.x(), wall.b.x()) ||
      x.x() - grown > std::max(wall.a.x(), wall.b.x()) ||
      x.y() + grown < std::min(wall.a.y(), wall.b.y()) ||
      x.y() - grown > std::max(wall.a.y(), wall.b.y()))
    return false;
  return touchWall(x, grown, wall, hit);
}

// A row's masses and targets, from its bodies (r.a, r.b), normal and reach,
// the distance of the centres (or of the centre from the wall) and the
// mixed material.
inline void fillRow(const ScaleBodies& s, const ContactMaterial& m, double dist,
                    ScaleSolver::Row& r) {
  const int a = r.a, b = r.b;
  const double invA = s.invMass[a], invB = b >= 0 ? s.invMass[b] : 0.0;
  r.massN = 1.0 / (invA + invB);
  r.friction = m.friction;
  if (m.friction > 0.0) {
    const double ra = s.radius[a], rb = b >= 0 ? s.radius[b] : 0.0;
    const double jb = b >= 0 ? rb * rb * s.invInertia[b] : 0.0;
    r.massT = 1.0 / (invA + invB + ra * ra * s.invInertia[a] + jb);
  }
  // The approach the bodies brought into the step: what this step's
  // forces added is cancelled, not bounced (docs/physics.md).
  const Vec2 vb = b >= 0 ? s.velocity[b] : Vec2::Zero();
  const double gn = (vb - s.velocity[a]).dot(r.normal);
  double forced = 0.0;
  if (!s.forcedVelocity.empty()) {
    const Vec2 fb = b >= 0 ? s.forcedVelocity[b] : Vec2::Zero();
    forced = (fb - s.forcedVelocity[a]).dot(r.normal);
  }
  const double brought = gn - forced;
  if (dist > r.reach * (1.0 + kTouchSlop)) {
    // Apart: may approach by at most the gap within the step. If the
    // approach closes the gap, the bodies collide within this step, and
    // the restitution pass gives them their bounce: without it every
    // impact caught early would be perfectly inelastic (an elastic gas
    // of 1,000 balls lost 10 % of its energy in 0.25 s).
    const double gap = dist - r.reach;
    r.target = -gap / s.dt;
    if (brought * s.dt < -gap) r.bounce = -m.restitution * brought;
  } else {
    // Touching: bounce the approach brought into the step.
    r.target = brought < 0.0 ? -m.restitution * brought : 0.0;
  }
}

}  // namespace

// The grid: cells as wide as the largest diameter plus the margin, balls
// counting-sorted into them (in index order within a cell).
ScaleSolver::Grid ScaleSolver::buildGrid(const ScaleBodies& s) {
  const std::size_t n = s.position.size();
  Vec2 lo = s.position[0], hi = s.position[0];
  double maxRadius = 0.0;
  bool finite = true;
  for (std::size_t i = 0; i < n; ++i) {
    lo = lo.cwiseMin(s.position[i]);
    hi = hi.cwiseMax(s.position[i]);
    maxRadius = std::max(maxRadius, s.radius[i]);
    finite = finite && s.position[i].allFinite();
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
  cellStart_.assign(static_cast<std::size_t>(cols) * rows + 1, 0);
  ballCell_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    int c = 0;
    if (finite) {
      const int cx = std::min(cols - 1, static_cast<int>((s.position[i].x() - lo.x()) * inv));
      const int cy = std::min(rows - 1, static_cast<int>((s.position[i].y() - lo.y()) * inv));
      c = cy * cols + cx;
    }
    ballCell_[i] = c;
    ++cellStart_[static_cast<std::size_t>(c) + 1];
  }
  for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
  // Each ball's position, radius and index in cell order: the three cells
  // of a grid row around a ball are one contiguous run of this array.
  cellBalls_.resize(n);
  std::vector<int> next(cellStart_.begin(), cellStart_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = static_cast<std::size_t>(next[static_cast<std::size_t>(ballCell_[i])]++);
    cellBalls_[k] = {s.position[i], s.radius[i], static_cast<int>(i)};
  }
  return {cols, rows, margin};
}

void ScaleSolver::findRows(const ScaleBodies& s, ThreadPool& pool) {
  const std::size_t n = s.position.size();
  const auto [cols, rows, margin] = buildGrid(s);

  // Rows are split into vertical strips of kStripColumns grid columns, so a
  // row joins balls of the same or of neighbouring strips; a row belongs to
  // the strip of its left ball. Rows of two even strips (or of two odd
  // strips) then share no ball: all even strips can be solved at once, each in
  // key order (Gauss-Seidel), then all odd strips. The strips depend on the
  // positions only, never on the thread count, so the result is the same for
  // any count.
  const int strips = std::clamp(cols / kStripColumns, 1, kMaxStrips);
  const int threads = pool.size();
  const std::size_t width = static_cast<std::size_t>(strips) + 1;
  // Each thread's counters on cache lines of their own (16 ints = 64 bytes).
  const std::size_t stride = (width + 15) / 16 * 16;
  stripOf_.resize(n);
  stripCount_.assign(static_cast<std::size_t>(threads) * stride, 0);
  stripStart_.assign(width, 0);
  found_.resize(static_cast<std::size_t>(threads));
  std::vector<std::size_t> offset(static_cast<std::size_t>(threads) + 1, 0);
  const std::uint64_t wallBase = n;
  const CellBall* cells = cellBalls_.data();
  pool.run([&](int t) {
    const auto [begin, end] = part(n, t, threads);
    // Whole grid columns per strip: neighbours are at most one column apart.
    for (std::size_t i = begin; i < end; ++i) stripOf_[i] = (ballCell_[i] % cols) * strips / cols;
    pool.sync();

    // First the pairs only (8 bytes each), in key order, counted per strip;
    // then, once every thread's counts are known, each row is made in its
    // place in strip order. Making the 96-byte rows first and moving them
    // into strip order afterwards cost a tenth of the step at N = 100,000.
    std::vector<Link>& links = found_[static_cast<std::size_t>(t)].links;
    links.clear();
    int* count = stripCount_.data() + static_cast<std::size_t>(t) * stride;
    std::vector<int> partners;  // this ball's, then sorted: rows in key order
    for (std::size_t ia = begin; ia < end; ++ia) {
      const int a = static_cast<int>(ia);
      const Vec2 xa = s.position[ia];
      const double ra = s.radius[ia];
      const int sa = stripOf_[ia];
      const int cx = ballCell_[ia] % cols, cy = ballCell_[ia] / cols;
      const int x0 = std::max(0, cx - 1), x1 = std::min(cols - 1, cx + 1);
      const int y0 = std::max(0, cy - 1), y1 = std::min(rows - 1, cy + 1);
      std::array<std::pair<int, int>, 3> runs{};
      std::size_t candidates = 0;
      for (int y = y0; y <= y1; ++y) {
        const std::size_t row = static_cast<std::size_t>(y) * static_cast<std::size_t>(cols);
        std::pair<int, int>& run = runs[static_cast<std::size_t>(y - y0)];
        run = {cellStart_[row + static_cast<std::size_t>(x0)],
               cellStart_[row + static_cast<std::size_t>(x1) + 1]};
        candidates += static_cast<std::size_t>(run.second - run.first);
      }
      partners.resize(candidates);
      int* near = partners.data();
      for (int y = y0; y <= y1; ++y) {
        const std::pair<int, int> run = runs[static_cast<std::size_t>(y - y0)];
        near = nearBalls(cells + run.first, cells + run.second, a, xa, ra, margin, near);
      }
      partners.resize(static_cast<std::size_t>(near - partners.data()));
      // Key order within the ball: by partner index.
      std::sort(partners.begin(), partners.end());
      for (const int b : partners) {
        links.push_back({a, b});
        ++count[std::min(sa, stripOf_[static_cast<std::size_t>(b)])];
      }
      for (std::size_t w = 0; w < s.walls.size(); ++w) {
        WallHit hit;
        if (!nearWall(xa, ra + margin, s.walls[w], hit)) continue;
        links.push_back({a, -1 - static_cast<int>(w)});
        ++count[sa];
      }
    }
    pool.sync();
    if (t == 0) {
      for (int u = 0; u < threads; ++u)
        offset[static_cast<std::size_t>(u) + 1] =
            offset[static_cast<std::size_t>(u)] + found_[static_cast<std::size_t>(u)].links.size();
      slot_.resize(offset.back());
      rows_.resize(offset.back());
      pairs_.resize(offset.back());
      // Where each thread's rows of each strip start: strip by strip, thread
      // by thread, so that a strip's rows are in key order (thread t has the
      // t-th range of balls).
      int at = 0;
      for (int st = 0; st < strips; ++st) {
        stripStart_[static_cast<std::size_t>(st)] = at;
        for (int u = 0; u < threads; ++u) {
          int& c = stripCount_[static_cast<std::size_t>(u) * stride + static_cast<std::size_t>(st)];
          const int rowsHere = c;
          c = at;
          at += rowsHere;
        }
      }
      stripStart_[static_cast<std::size_t>(strips)] = at;
    }
    pool.sync();

    // The last step's impulses are sorted by key, as these rows are made.
    auto last =
        std::lower_bound(lastKey_.begin(), lastKey_.end(), static_cast<std::uint64_t>(begin) << 32);
    int* slot = slot_.data() + offset[static_cast<std::size_t>(t)];
    for (std::size_t k = 0; k < links.size(); ++k) {
      const int a = links[k].a, b = links[k].b;
      const std::size_t ia = static_cast<std::size_t>(a);
      Row r;
      r.a = a;
      r.b = b;
      double dist = 0.0;
      ContactMaterial m;
      if (b >= 0) {
        const Vec2 d = s.position[static_cast<std::size_t>(b)] - s.position[ia];
        r.reach = s.radius[ia] + s.radius[static_cast<std::size_t>(b)];
        dist = std::sqrt(d.squaredNorm());
        r.normal = dist > 0.0 ? Vec2(d / dist) : Vec2(1.0, 0.0);
        m = mixMaterials(s.material[ia], s.material[static_cast<std::size_t>(b)]);
      } else {
        const std::size_t w = static_cast<std::size_t>(-1 - b);
        WallHit hit;
        nearWall(s.position[ia], s.radius[ia] + margin, s.walls[w], hit);
        r.reach = s.radius[ia];
        dist = s.radius[ia] + margin - hit.overlap;
        r.normal = hit.normal;
        m = mixMaterials(s.material[ia], s.wallMaterial[w]);
      }
      fillRow(s, m, dist, r);
      const std::uint64_t other =
          b >= 0 ? static_cast<std::uint64_t>(b) : wallBase + static_cast<std::uint64_t>(-1 - b);
      r.key = (static_cast<std::uint64_t>(a) << 32) | other;
      // Warm start from the last step's row with the same key, if any.
      while (last != lastKey_.end() && *last < r.key) ++last;
      if (last != lastKey_.end() && *last == r.key) {
        const std::size_t j = static_cast<std::size_t>(last - lastKey_.begin());
        r.lambdaN = lastN_[j];
        r.lambdaT = lastT_[j];
      }
      const int st =
          b >= 0 ? std::min(stripOf_[ia], stripOf_[static_cast<std::size_t>(b)]) : stripOf_[ia];
      const int pos = count[st]++;
      rows_[static_cast<std::size_t>(pos)] = r;
      pairs_[static_cast<std::size_t>(pos)] = {a, b, r.reach};
      slot[k] = pos;
    }
  });
}

}  // namespace particles
