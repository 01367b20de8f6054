#include "particles/scale_solver.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "particles/broad_phase.h"
#include "particles/world.h"

namespace particles {
namespace {

// The same contact test as the broad phase (broad_phase.cpp) and the same
// rounding floor as the small-scene overlap removal (world.cpp).
constexpr double kTouchSlop = 1e-9;
constexpr double kOverlapTolerance = 1e-9;
// Pairs closer than this fraction of the largest radius (beyond touching)
// become rows too: "speculative" rows that let the two approach by at most
// their gap within the step, so that a contact that closes during the step
// is caught by the velocity solve and then by the overlap removal, with one
// pair search per step.
constexpr double kMarginFraction = 0.2;
// Upper bound on the strips of the parallel solve (even: a fixed number, so
// that no result depends on the thread count).
constexpr int kMaxStrips = 32;
// Grid columns per strip, at least: within a strip the rows are solved in
// key order, which for a pile numbered row by row from the bottom is close
// to bottom-up; wider strips keep more of that order. Measured on the pile
// (docs/scale.md): 1 column, 12.8 % max overlap at N = 10,000; 4, 10.6 %;
// 8, 8.0 %; 16, 9.5 %.
constexpr int kStripColumns = 8;

// Items [begin, end) of part t of T: a split by index only, never by timing.
std::pair<std::size_t, std::size_t> part(std::size_t n, int t, int threads) {
  const std::size_t tt = static_cast<std::size_t>(t), tn = static_cast<std::size_t>(threads);
  return {n * tt / tn, n * (tt + 1) / tn};
}

// Applies P = dn n + dt tau to the two bodies of a row (b < 0: a wall, which
// takes nothing). Signs as in contact_impulse_impl.h: b gets +P, a gets -P,
// and both spins change by -r dt / J.
inline void applyRow(ScaleSolver::Motion* m, const ScaleSolver::Row& r, double dn, double dt) {
  const Vec2 p = dn * r.normal + dt * perpLeft(r.normal);
  ScaleSolver::Motion& a = m[r.a];
  a.velocity -= a.invMass * p;
  a.angularVelocity -= a.radius * dt * a.invInertia;
  if (r.b >= 0) {
    ScaleSolver::Motion& b = m[r.b];
    b.velocity += b.invMass * p;
    b.angularVelocity -= b.radius * dt * b.invInertia;
  }
}

// The change of a row's accumulated friction impulse that cancels the
// tangential relative velocity gt, clamped so that |lambdaT| <= mu lambdaN
// (no bound for mu = infinity, no-slip); the row keeps the new total.
inline double frictionChange(ScaleSolver::Row& r, double gt) {
  double lt = r.lambdaT - gt * r.massT;
  if (!std::isinf(r.friction)) {
    const double bound = r.friction * r.lambdaN;
    lt = std::clamp(lt, -bound, bound);
  }
  const double dt = lt - r.lambdaT;
  r.lambdaT = lt;
  return dt;
}

// One projected Gauss-Seidel update of a row's accumulated impulses:
// friction first (bounded by the normal impulse it has so far), then the
// normal impulse, which never pulls (lambdaN >= 0) and brings the normal
// relative velocity up to at least `target`. The balls are read once and
// written once: a row waits for the last row that touched its balls, so
// every load and store saved shortens that chain (about 7 % of the 10,000-ball
// pile's step, bit-identical results).
inline void solveBallRow(ScaleSolver::Motion& a, ScaleSolver::Motion& b, ScaleSolver::Row& r) {
  const Vec2 n = r.normal, tau = perpLeft(n);
  Vec2 va = a.velocity, vb = b.velocity;
  // A row without impulse whose bodies already part fast enough (most
  // speculative rows): friction bounded by mu * 0 and a normal impulse
  // clamped at 0 would change nothing, so nothing is computed or stored.
  if (r.lambdaN == 0.0 && r.lambdaT == 0.0 && (vb - va).dot(n) >= r.target) return;
  double wa = a.angularVelocity, wb = b.angularVelocity;
  if (r.friction > 0.0) {
    const double gt = (vb - va).dot(tau) - wb * b.radius - wa * a.radius;
    const double dt = frictionChange(r, gt);
    const Vec2 p = dt * tau;
    va -= a.invMass * p;
    wa -= a.radius * dt * a.invInertia;
    vb += b.invMass * p;
    wb -= b.radius * dt * b.invInertia;
  }
  const double gn = (vb - va).dot(n);
  const double ln = std::max(0.0, r.lambdaN + (r.target - gn) * r.massN);
  const Vec2 p = (ln - r.lambdaN) * n;
  r.lambdaN = ln;
  a.velocity = va - a.invMass * p;
  b.velocity = vb + b.invMass * p;
  a.angularVelocity = wa;
  b.angularVelocity = wb;
}

// The same for a ball and a wall, which has no velocity and takes nothing.
inline void solveWallRow(ScaleSolver::Motion& a, ScaleSolver::Row& r) {
  const Vec2 n = r.normal, tau = perpLeft(n);
  Vec2 va = a.velocity;
  if (r.lambdaN == 0.0 && r.lambdaT == 0.0 && -va.dot(n) >= r.target) return;
  double wa = a.angularVelocity;
  if (r.friction > 0.0) {
    const double gt = -va.dot(tau) - wa * a.radius;
    const double dt = frictionChange(r, gt);
    va -= a.invMass * (dt * tau);
    wa -= a.radius * dt * a.invInertia;
  }
  const double gn = -va.dot(n);
  const double ln = std::max(0.0, r.lambdaN + (r.target - gn) * r.massN);
  const double dn = ln - r.lambdaN;
  r.lambdaN = ln;
  a.velocity = va - a.invMass * (dn * n);
  a.angularVelocity = wa;
}

inline void solveRow(ScaleSolver::Motion* m, ScaleSolver::Row& r) {
  if (r.b >= 0)
    solveBallRow(m[r.a], m[r.b], r);
  else
    solveWallRow(m[r.a], r);
}

// The restitution pass for a speculative row that closed its gap (bounce >
// 0) and needed a normal impulse to do so: raises the normal relative
// velocity to the bounce, with the accumulated impulse kept >= 0. Touching
// rows already have their bounce in their target.
inline void restituteRow(ScaleSolver::Motion* m, ScaleSolver::Row& r) {
  if (r.bounce <= 0.0 || r.lambdaN <= 0.0) return;
  const Vec2 vb = r.b >= 0 ? m[r.b].velocity : Vec2::Zero();
  const double gn = (vb - m[r.a].velocity).dot(r.normal);
  const double ln = std::max(0.0, r.lambdaN + (r.bounce - gn) * r.massN);
  const double dn = ln - r.lambdaN;
  r.lambdaN = ln;
  if (dn != 0.0) applyRow(m, r, dn, 0.0);
}

// Moves a row's bodies apart by their whole overlap, shared by inverse mass
// (a wall takes none): the small-scene projection of world.cpp, per row,
// except that under gravity the lower ball's share is scaled by
// 1 - shock |n . down| (SolverSettings::scaleShockPropagation).
// Returns the overlap found (m, <= 0 when apart).
inline double projectRow(const ScaleBodies& s, const ScaleSolver::Pair& r, double shock) {
  const int a = r.a;
  if (r.b < 0) {
    WallHit hit;
    if (!touchWall(s.position[a], s.radius[a], s.walls[static_cast<std::size_t>(-1 - r.b)], hit))
      return 0.0;
    if (hit.overlap <= kOverlapTolerance * r.reach) return hit.overlap;
    s.position[a] -= hit.overlap * hit.normal;
    return hit.overlap;
  }
  const int b = r.b;
  const Vec2 d = s.position[b] - s.position[a];
  const double dist2 = d.squaredNorm();
  // Apart (most speculative rows): no square root. Nothing moves, and an
  // overlap <= 0 changes neither the deepest overlap seen nor the flags.
  if (dist2 >= r.reach * r.reach) return 0.0;
  const double dist = std::sqrt(dist2);
  const double overlap = r.reach - dist;
  if (overlap <= kOverlapTolerance * r.reach) return overlap;
  const Vec2 n = dist > 0.0 ? Vec2(d / dist) : Vec2(1.0, 0.0);
  double wa = s.invMass[a], wb = s.invMass[b];
  if (shock > 0.0) {
    const double below = n.dot(s.down);  // > 0: b lies below a
    const double lowA = wa * (1.0 + shock * std::min(0.0, below));
    const double lowB = wb * (1.0 - shock * std::max(0.0, below));
    // An immovable upper ball on a movable lower one: the lower one moves.
    if (lowA + lowB > 0.0) {
      wa = lowA;
      wb = lowB;
    }
  }
  const double share = overlap / (wa + wb);
  s.position[a] -= share * wa * n;
  s.position[b] += share * wb * n;
  return overlap;
}

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

void ScaleSolver::reset() {
  lastKey_.clear();
  lastN_.clear();
  lastT_.clear();
}

std::size_t ScaleSolver::memoryBytes() const {
  std::size_t bytes =
      sizeof(Row) * rows_.capacity() + sizeof(Pair) * pairs_.capacity() +
      sizeof(Motion) * motion_.capacity() +
      sizeof(int) * (stripStart_.capacity() + stripCount_.capacity()) +
      sizeof(std::uint64_t) * lastKey_.capacity() + sizeof(int) * stripOf_.capacity() +
      sizeof(int) * slot_.capacity() + sizeof(double) * (lastN_.capacity() + lastT_.capacity()) +
      sizeof(int) * (cellStart_.capacity() + ballCell_.capacity()) +
      sizeof(CellBall) * cellBalls_.capacity() + sizeof(ThreadLinks) * found_.capacity();
  for (const ThreadLinks& f : found_) bytes += sizeof(Link) * f.links.capacity();
  return bytes;
}

// The grid: cells as wide as the largest diameter plus the margin, balls
// counting-sorted into them (in index order within a cell).
void ScaleSolver::findRows(const ScaleBodies& s, ThreadPool& pool) {
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
  gridCols_ = cols;

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

void ScaleSolver::step(const ScaleBodies& s, const SolverSettings& settings, StepStats& stats,
                       std::vector<ImpactEvent>* impacts) {
  const std::size_t n = s.position.size();
  if (n == 0) return;
  // Below scaleParallelFrom balls a step is too short for the threads'
  // barriers to pay (docs/scale.md): one thread, the same bits.
  const bool parallel = static_cast<long long>(n) >= settings.scaleParallelFrom;
  ThreadPool& pool = pool_.get(parallel ? std::max(1, settings.threads) : 1);
  const int threads = pool.size();
  findRows(s, pool);

  const int iterations = std::max(1, settings.scaleVelocityIterations);
  const int passes = std::max(1, settings.scalePositionPasses);
  const double shock = std::clamp(settings.scaleShockPropagation, 0.0, 1.0);
  // What each thread saw of the overlap, written once per row: one cache
  // line per thread, or the two threads fight over one line on every row
  // (measured: 2 threads gained 1.07x at N = 10,000 with them side by side).
  struct alignas(64) Seen {
    double deepest = 0.0;
    std::array<char, 2> moved{0, 0};
  };
  std::vector<Seen> seen(static_cast<std::size_t>(threads));
  int passesUsed = 0;

  // Runs f on every row: the even strips shared among the threads, then
  // the odd ones (strips of one parity share no ball).
  const int strips = static_cast<int>(stripStart_.size()) - 1;
  // A thread takes its strips of one parity row by row in turn (strip 0's
  // first row, strip 2's first row, ..., strip 0's second row, ...): the
  // strips share no ball, so the result is bit for bit that of solving them
  // one after another, but consecutive rows no longer wait for each other.
  // Within a strip each row waits for the last one that touched its balls
  // (key order puts a ball's rows side by side), so one strip at a time
  // leaves the core idle on that chain of loads and stores.
  auto byStrip = [&](int t, auto&& f) {
    for (int parity = 0; parity < 2; ++parity) {
      std::array<std::size_t, kMaxStrips> at{}, end{};
      // Thread t takes a block of neighbouring strips, so that the two
      // threads share only the balls along one strip border.
      const int count = (strips - parity + 1) / 2;
      int active = 0, index = 0;
      for (int st = parity; st < strips; st += 2, ++index) {
        if (index * threads / count != t) continue;
        const std::size_t i = static_cast<std::size_t>(st);
        at[static_cast<std::size_t>(active)] = static_cast<std::size_t>(stripStart_[i]);
        end[static_cast<std::size_t>(active)] = static_cast<std::size_t>(stripStart_[i + 1]);
        if (at[static_cast<std::size_t>(active)] < end[static_cast<std::size_t>(active)]) ++active;
      }
      while (active > 0) {
        for (int j = 0; j < active;) {
          const std::size_t u = static_cast<std::size_t>(j);
          f(at[u]++);
          if (at[u] == end[u]) {
            // This strip is done: the last active one takes its place.
            --active;
            at[u] = at[static_cast<std::size_t>(active)];
            end[u] = end[static_cast<std::size_t>(active)];
          } else {
            ++j;
          }
        }
      }
      pool.sync();
    }
  };

  motion_.resize(n);
  Motion* m = motion_.data();
  pool.run([&](int t) {
    // Each ball's velocity and mass properties in one cache line: a row
    // touches two of them, in an order the strips decide.
    const auto [b, e] = part(n, t, threads);
    for (std::size_t i = b; i < e; ++i)
      m[i] = {s.velocity[i], s.angularVelocity[i], s.invMass[i], s.invInertia[i], s.radius[i]};
    pool.sync();
    // Warm start: the last step's impulses, applied again.
    byStrip(t, [&](std::size_t k) {
      Row& r = rows_[k];
      if (r.lambdaN != 0.0 || r.lambdaT != 0.0) applyRow(m, r, r.lambdaN, r.lambdaT);
    });
    for (int it = 0; it < iterations; ++it)
      byStrip(t, [&](std::size_t k) { solveRow(m, rows_[k]); });
    byStrip(t, [&](std::size_t k) { restituteRow(m, rows_[k]); });

    for (std::size_t i = b; i < e; ++i) {
      s.velocity[i] = m[i].velocity;
      s.angularVelocity[i] = m[i].angularVelocity;
    }
    for (std::size_t i = b; i < e; ++i) s.position[i] += s.dt * s.velocity[i];
    if (s.spin)
      for (std::size_t i = b; i < e; ++i) s.angle[i] += s.dt * s.angularVelocity[i];
    pool.sync();

    double& deepest = seen[static_cast<std::size_t>(t)].deepest;
    for (int pass = 0; pass < passes; ++pass) {
      char& mine = seen[static_cast<std::size_t>(t)].moved[static_cast<std::size_t>(pass % 2)];
      mine = 0;
      byStrip(t, [&](std::size_t k) {
        const Pair& r = pairs_[k];
        const double overlap = projectRow(s, r, shock);
        if (pass == 0) deepest = std::max(deepest, overlap);
        if (overlap > kOverlapTolerance * r.reach) mine = 1;
      });
      bool any = false;
      for (const Seen& m : seen) any = any || m.moved[static_cast<std::size_t>(pass % 2)] != 0;
      if (t == 0 && any) passesUsed = pass + 1;
      if (!any) break;
      pool.sync();  // nobody rewrites this pass's flags before all have read them
    }
  });

  // Keep this step's impulses, in key order, for the next step's warm start.
  lastKey_.resize(slot_.size());
  lastN_.resize(slot_.size());
  lastT_.resize(slot_.size());
  pool.run([&](int t) {
    const auto [b, e] = part(slot_.size(), t, threads);
    for (std::size_t k = b; k < e; ++k) {
      const Row& r = rows_[static_cast<std::size_t>(slot_[k])];
      lastKey_[k] = r.key;
      lastN_[k] = r.lambdaN;
      lastT_[k] = r.lambdaT;
    }
  });
  if (impacts) {
    impacts->clear();
    for (std::size_t k = 0; k < slot_.size(); ++k) {
      const Row& r = rows_[static_cast<std::size_t>(slot_[k])];
      if (r.lambdaN == 0.0) continue;
      const bool wall = r.b < 0;
      impacts->push_back({r.a, wall ? -1 - r.b : r.b, wall, r.normal, r.lambdaN, r.lambdaT,
                          r.friction == 0.0 ? 0.0 : r.friction * r.lambdaN});
    }
  }
  stats.contacts = static_cast<int>(rows_.size());
  stats.passes = iterations;
  stats.correctionPasses = passesUsed;
  double deepest = 0.0;
  for (const Seen& m : seen) deepest = std::max(deepest, m.deepest);
  stats.maxOverlap = deepest;
}

}  // namespace particles
