#include "particles/scale_solver.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include "particles/broad_phase.h"
#include "particles/contact_impulse.h"
#include "particles/material.h"
#include "particles/swept_wall.h"
#include "particles/world.h"
#include "scale_common.h"
#include "scale_soft.h"

namespace particles {
namespace {

// Strips a thread solves interleaved at a time (byStrip in ScaleSolver::step).
constexpr int kInterleave = 8;

// The same rounding floor as the small-scene overlap removal (world.cpp).
constexpr double kOverlapTolerance = 1e-9;

using scale::applyRow;
using scale::frictionChange;
using scale::kMaxStrips;
using scale::part;

// The warm start of a row: its accumulated impulses, applied again.
inline void warmStartRow(ScaleSolver::Motion* m, const ScaleSolver::Row& r) {
  if (r.lambdaN != 0.0 || r.lambdaT != 0.0) applyRow(m, r, r.lambdaN, r.lambdaT);
}

// A row's two updates in their order: the friction, then the normal impulse
// over-relaxed by `relax`; in the last iteration (kLast) the plain normal
// impulse first (solveBallRow says why).
template <bool kLast, typename Friction, typename Normal>
inline void inOrder(Friction&& friction, Normal&& normal, double relax) {
  if constexpr (kLast) {
    normal(1.0);
    friction();
  } else {
    friction();
    normal(relax);
  }
}

// One projected Gauss-Seidel update of a row's accumulated impulses: the
// friction (bounded by the normal impulse it has so far) and the normal
// impulse, which never pulls (lambdaN >= 0) and brings the normal relative
// velocity up to at least `target`. The normal change is over-relaxed by
// `relax` (SolverSettings::scaleOverRelaxation). In the last iteration
// (kLast) the normal impulse comes first and is not over-relaxed: one such
// update makes an isolated row's normal impulse exact, and the friction
// then has its exact Coulomb bound. The balls are read once and written
// once: a row waits for the last row that touched its balls, so every load
// and store saved shortens that chain (about 7 % of the 10,000-ball pile's
// step, bit-identical results).
template <bool kLast>
inline void solveBallRow(ScaleSolver::Motion& a, ScaleSolver::Motion& b, ScaleSolver::Row& r,
                         double relax) {
  const Vec2 n = r.normal(), tau = perpLeft(n);
  Vec2 va = a.velocity, vb = b.velocity;
  // A row without impulse whose bodies already part fast enough (most
  // speculative rows): friction bounded by mu * 0 and a normal impulse
  // clamped at 0 would change nothing, so nothing is computed or stored.
  if (r.lambdaN == 0.0 && r.lambdaT == 0.0 && (vb - va).dot(n) >= r.target) return;
  double wa = a.angularVelocity, wb = b.angularVelocity;
  const auto friction = [&] {
    if (r.friction <= 0.0) return;
    const double gt = (vb - va).dot(tau) - wb * b.radius - wa * a.radius;
    const double dt = frictionChange(r, gt);
    const Vec2 p = dt * tau;
    va -= a.invMass * p;
    wa -= a.radius * dt * a.invInertia;
    vb += b.invMass * p;
    wb -= b.radius * dt * b.invInertia;
  };
  const auto normal = [&](double w) {
    const double gn = (vb - va).dot(n);
    const double ln = std::max(0.0, r.lambdaN + w * (r.target - gn) * r.massN);
    const Vec2 p = (ln - r.lambdaN) * n;
    r.lambdaN = ln;
    va -= a.invMass * p;
    vb += b.invMass * p;
  };
  inOrder<kLast>(friction, normal, relax);
  a.velocity = va;
  b.velocity = vb;
  a.angularVelocity = wa;
  b.angularVelocity = wb;
}

// The same for a ball and a wall, which has no velocity and takes nothing.
template <bool kLast>
inline void solveWallRow(ScaleSolver::Motion& a, ScaleSolver::Row& r, double relax) {
  const Vec2 n = r.normal(), tau = perpLeft(n);
  Vec2 va = a.velocity;
  if (r.lambdaN == 0.0 && r.lambdaT == 0.0 && -va.dot(n) >= r.target) return;
  double wa = a.angularVelocity;
  const auto friction = [&] {
    if (r.friction <= 0.0) return;
    const double gt = -va.dot(tau) - wa * a.radius;
    const double dt = frictionChange(r, gt);
    va -= a.invMass * (dt * tau);
    wa -= a.radius * dt * a.invInertia;
  };
  const auto normal = [&](double w) {
    const double gn = -va.dot(n);
    const double ln = std::max(0.0, r.lambdaN + w * (r.target - gn) * r.massN);
    const double dn = ln - r.lambdaN;
    r.lambdaN = ln;
    va -= a.invMass * (dn * n);
  };
  inOrder<kLast>(friction, normal, relax);
  a.velocity = va;
  a.angularVelocity = wa;
}

template <bool kLast>
inline void solveRow(ScaleSolver::Motion* m, ScaleSolver::Row& r, double relax) {
  if (r.b >= 0)
    solveBallRow<kLast>(m[r.a], m[r.b], r, relax);
  else
    solveWallRow<kLast>(m[r.a], r, relax);
}

// Raises a row's normal relative velocity to `bounce` with its accumulated
// normal impulse kept >= 0, then updates its friction once more against the
// slip left, within the new Coulomb bound; returns the changes of the row's
// impulses. Unguarded: the rigid step (restituteRow) and the soft step
// decide which rows bounce. The friction update is what makes a speculative
// row's impact Walton's: the passes bound its friction by mu times the
// impulse that closes the gap, a part of the (1 + e) M_n g_n the impact
// ends with: an oblique hit caught 1 mm before contact got 0.05 N s of
// friction instead of Walton's 0.15, and a rough gas at mu = 0.1 gained a
// fifth of the spin the kinetic theory gives (docs/scale.md, "The rough
// gas"). A row whose bodies another impact already sends apart faster than
// its bounce gives normal impulse back, and its friction falls to the new
// bound with it.
struct RowChange {
  double normal = 0.0;   // N s
  double tangent = 0.0;  // N s
};

inline RowChange raiseNormalTo(ScaleSolver::Motion* m, ScaleSolver::Row& r, double bounce) {
  const ScaleSolver::Motion& a = m[r.a];
  const ScaleSolver::Motion* b = r.b >= 0 ? &m[r.b] : nullptr;  // a wall: none
  // b's velocity relative to a's, read when called (the slip after the
  // normal impulse); a wall stands still.
  const auto relative = [&]() -> Vec2 { return (b ? b->velocity : Vec2::Zero()) - a.velocity; };
  const Vec2 n = r.normal();
  const double ln = std::max(0.0, r.lambdaN + (bounce - relative().dot(n)) * r.massN);
  RowChange c;
  c.normal = ln - r.lambdaN;
  r.lambdaN = ln;
  if (c.normal != 0.0) applyRow(m, r, c.normal, 0.0);
  if (r.friction > 0.0) {
    const double spinB = b ? b->angularVelocity * b->radius : 0.0;
    c.tangent =
        frictionChange(r, relative().dot(perpLeft(n)) - spinB - a.angularVelocity * a.radius);
    if (c.tangent != 0.0) applyRow(m, r, 0.0, c.tangent);
  }
  return c;
}

// The restitution pass for a speculative row that closed its gap (bounce >
// 0) and needed a normal impulse to do so: raises the normal relative
// velocity to the bounce. Touching rows already have their bounce in their
// target.
inline void restituteRow(ScaleSolver::Motion* m, ScaleSolver::Row& r, double bounce) {
  if (bounce <= 0.0 || r.lambdaN <= 0.0) return;
  raiseNormalTo(m, r, bounce);
}

// The support sweep's slope: ball pairs whose normal is at least this far
// from horizontal (|n . down| >= 0.2, about 11.5 degrees) have an upper and a
// lower ball. Measured over 8 seeds of the 10,000 pile (docs/scale.md):
// 0.05, 0.2, 0.35, 0.5 and 0.8 gave mean max overlaps of 2.8, 3.0, 4.1, 3.8
// and 7.8 %; 0.2 also gave the polydisperse pile 4.4 % against 8.3 % for 0.5.
constexpr double kSupportSlope = 0.2;

// How much faster against gravity than its lower partner (or than itself
// before) the support sweep may leave an upper ball, in steps of gravity
// (|g| dt). A quiet pile moves by far less than |g| dt, so the bound only
// meets violent sweeps. Over 24 seeds of the 2,000 pile (docs/scale.md,
// "Walls with a side"): 20 of 24 at rest by step 400 with 1, as with no
// bound (20; mean rest step 347 against 329, within the seeds' spread);
// 0 slowed it (12 seeds: from step ~375 instead of ~330).
constexpr double kSupportRiseAllowance = 1.0;

// Shock propagation in velocities (SolverSettings::scaleVelocityShock), one
// sweep after the iterations: a ball pair stacked along gravity that still
// approaches (normal relative velocity below min(target, 0)) stops
// approaching by a change of the upper ball's velocity alone, along n, as if
// the lower ball were immovable (Guendelman, Bridson and Fedkiw's shock
// propagation), up to a bound on its rise (below). The cell order runs bottom-up, so one sweep
// carries the support of the floor up a stack that 8 iterations leave sinking. No bounce is added
// (the goal is never above 0), spins are untouched (the push is through the centres), and an
// immovable upper ball is left to the iterations. It does not conserve momentum: the lower ball
// takes no reaction, as with a floor.
inline void supportRow(ScaleSolver::Motion* m, const ScaleSolver::Row& r, Vec2 down, double gdt) {
  if (r.b < 0) return;
  const Vec2 n = r.normal();
  const double below = n.dot(down);  // > 0: b lies below a
  if (std::abs(below) < kSupportSlope) return;
  ScaleSolver::Motion& upper = below > 0.0 ? m[r.a] : m[r.b];
  if (upper.invMass == 0.0) return;
  const Vec2 va = m[r.a].velocity, vb = m[r.b].velocity;
  const double gn = (vb - va).dot(n);
  const double goal = std::min(r.target, 0.0);
  if (gn >= goal) return;
  // a moves along -n, b along +n: either way the pair parts by goal - gn.
  Vec2 v = upper.velocity + (below > 0.0 ? gn - goal : goal - gn) * n;
  // But no faster against gravity than the lower ball, or than the upper
  // one already was, give or take kSupportRiseAllowance. Without that bound a ball on two lower
  // balls could leave faster than both (1.11 times their speed at 35 degrees), and the sweep,
  // bottom-up, compounded it layer by layer: at step 1,055 of the 100,000 pile a region 70 layers
  // deep went from 1 m/s to 570 m/s in one step (docs/scale.md, "Walls with a side"). With it, a
  // ball L layers up leaves the sweep rising at most L allowances faster than the fastest rising
  // ball below it: linear, not geometric.
  const ScaleSolver::Motion& lower = below > 0.0 ? m[r.b] : m[r.a];
  const double rise = -v.dot(down);
  const double limit =
      std::max(-upper.velocity.dot(down), -lower.velocity.dot(down)) + kSupportRiseAllowance * gdt;
  if (rise > limit) v += (rise - limit) * down;
  upper.velocity = v;
}

// A ball moving further this step than the rows' margin (0.2 of the largest
// radius, scale_rows.cpp; 0.2 of its own is a safe test) may reach a wall
// it has no row with: its speed can come from this step's impulses, as when
// a ball landing on the 100,000 pile is thrown sideways at 30 m/s
// (docs/scale.md, "Walls with a side").
inline bool movesPastTheMargin(const Vec2& v, double radius, double dt) {
  const double reach = 0.2 * radius;
  return v.squaredNorm() * (dt * dt) > reach * reach;
}

// The wall guard for such a ball: if its straight path this step meets a
// wall (the first one met, swept_wall.h), it takes the impact there with the
// handout's impulse (resolveImpact: the ball is body a, the wall body b with
// zero inverse mass and inertia, the same code path as every wall contact),
// so the bounce is -e times the approach it brought, and friction and spin
// act as at any other wall. It moves with the old velocity up to the time of
// impact and with the new one after (as SolverSettings::sweptWalls does on
// the small path).
//
// A ball that starts the move on a wall (touching it or overlapping it) and
// moving into it takes that impact first, at t = 0: the sweep finds a flat
// side only from more than a radius away, so such a ball went straight
// through. The solve can leave one so: the stages after its wall row (the
// rows after it in the last iteration, the restitution of other rows, the
// support sweep, which skips wall rows) still change its velocity. In the
// 1,000,000 pile twelve balls crossed a side wall this way, by up to 0.68 m,
// and one stayed out (docs/scale.md, "The million for 600 steps"). A slow
// ball is left alone: it moves less than the rows' margin into the wall, and
// the overlap passes and the next step's wall row take it back.
//
// A ball may meet several walls in a step (a corner, where the floor's
// friction can turn its spin into a speed into the side wall): after each
// impact it moves on from the point of impact and is guarded again, up to
// this many impacts, and then moves freely for what is left of the step.
constexpr int kGuardImpacts = 4;

// Returns whether the ball struck a wall.
inline bool moveGuarded(ScaleSolver::CellBall& ball, ScaleSolver::Motion& m, const ScaleBodies& s) {
  bool hitAny = false;
  const auto index = static_cast<std::size_t>(ball.index);
  const auto impact = [&](std::size_t wall, const Vec2& normal) {
    ContactBody self{
        m.velocity, m.angularVelocity,
        m.invMass,  m.invInertia,
        m.radius,   s.forcedVelocity.empty() ? Vec2(0.0, 0.0) : s.forcedVelocity[index]};
    ContactBody theWall;
    resolveImpact(self, theWall, normal, mixMaterials(s.material[index], s.wallMaterial[wall]));
    m.velocity = self.velocity;
    m.angularVelocity = self.angularVelocity;
  };
  // The path's box grown by the radius, and a little more (a bound on the
  // rounding of sweepAgainstWall's exact tests): a wall outside it cannot
  // be met. While a large pile falls every ball is fast: at 100,000 balls
  // on two threads the sweeps were 8.8 % of the samples of 200 falling
  // steps, and with this test about 3 % less time (docs/scale.md, "The
  // wall guard's impact is the handout's"). Same results.
  const auto pathBox = [&](Vec2& lo, Vec2& hi, double time) {
    const Vec2 end = ball.position + time * m.velocity;
    const double grown = ball.radius * (1.0 + 1e-9) +
                         1e-12 * (std::fabs(ball.position.x()) + std::fabs(ball.position.y()) +
                                  std::fabs(end.x()) + std::fabs(end.y()));
    lo = Vec2(std::fmin(ball.position.x(), end.x()) - grown,
              std::fmin(ball.position.y(), end.y()) - grown);
    hi = Vec2(std::fmax(ball.position.x(), end.x()) + grown,
              std::fmax(ball.position.y(), end.y()) + grown);
  };
  double left = s.dt;  // s, the time still to move
  for (int impacts = 0; impacts < kGuardImpacts; ++impacts) {
    Vec2 lo, hi;
    pathBox(lo, hi, left);
    bool struck = false;
    for (std::size_t w = 0; w < s.walls.size(); ++w) {
      WallHit on;  // on.normal points from the ball to the wall
      if (scale::wallOutsideBox(lo, hi, s.walls[w]) ||
          !touchWall(ball.position, ball.radius, s.walls[w], on) ||
          m.velocity.dot(on.normal) <= 0.0)
        continue;
      impact(w, on.normal);
      struck = hitAny = true;
    }
    if (struck) pathBox(lo, hi, left);
    std::optional<SweptHit> first;
    std::size_t wall = 0;
    for (std::size_t w = 0; w < s.walls.size(); ++w) {
      if (scale::wallOutsideBox(lo, hi, s.walls[w])) continue;
      const std::optional<SweptHit> hit =
          sweepAgainstWall(ball.position, m.velocity, ball.radius, s.walls[w], left);
      if (hit && (!first || hit->time < first->time)) {
        first = hit;
        wall = w;
      }
    }
    // first->normal points from the ball to the wall: > 0 is approaching.
    if (!first || m.velocity.dot(first->normal) <= 0.0) break;
    ball.position += first->time * m.velocity;
    left -= first->time;
    impact(wall, first->normal);
    hitAny = true;
  }
  ball.position += left * m.velocity;
  return hitAny;
}

// How deep a pair's balls, or its ball and wall, overlap now (m; 0 when
// apart, or the wall's hit overlap). `hit` gets a wall's contact, `dist`
// the distance of two balls' centres when they touch. Balls are numbered in
// cell order.
inline double overlapOf(const ScaleSolver::CellBall* ball, const ScaleBodies& s,
                        const ScaleSolver::Pair& r, WallHit& hit, double& dist) {
  const Vec2& xa = ball[r.a].position;
  if (r.b < 0)
    return touchWall(xa, r.reach, s.walls[static_cast<std::size_t>(-1 - r.b)], hit) ? hit.overlap
                                                                                    : 0.0;
  const double dist2 = (ball[r.b].position - xa).squaredNorm();
  // Apart (most speculative rows): no square root. An overlap of 0 changes
  // neither the deepest overlap seen nor what is moved.
  if (dist2 >= r.reach * r.reach) return 0.0;
  dist = std::sqrt(dist2);
  return r.reach - dist;
}

// Moves a row's bodies apart by their whole overlap, shared by inverse mass
// (a wall takes none): the small-scene projection of world.cpp, per row.
// Under gravity with shock propagation (SolverSettings::scaleShockPropagation)
// the part of the move along gravity is shared with the lower ball's weight
// scaled by 1 - shock |n . down|; the part across gravity is still shared by
// inverse mass. Scaling the whole move instead pushed upper balls sideways
// more than their lower partners: the pair's centre shifted sideways on every
// pass, and shallow piles crept for ever instead of coming to rest
// (docs/scale.md, "Shock propagation").
// Returns the overlap found (m, <= 0 when apart). Balls are numbered in
// cell order: `ball` holds their positions, `invMass` their inverse masses.
inline double projectRow(ScaleSolver::CellBall* ball, const double* invMass, const ScaleBodies& s,
                         const ScaleSolver::Pair& r, double shock) {
  WallHit hit;
  double dist = 0.0;
  const double overlap = overlapOf(ball, s, r, hit, dist);
  if (overlap <= kOverlapTolerance * r.reach) return overlap;
  const int a = r.a;
  Vec2& xa = ball[a].position;
  if (r.b < 0) {
    xa -= overlap * hit.normal;
    return overlap;
  }
  const int b = r.b;
  Vec2& xb = ball[b].position;
  const Vec2 d = xb - xa;
  const Vec2 n = dist > 0.0 ? Vec2(d / dist) : Vec2(1.0, 0.0);
  const double wa = invMass[a], wb = invMass[b];
  if (shock > 0.0) {
    const double below = n.dot(s.down);  // > 0: b lies below a
    const double lowA = wa * (1.0 + shock * std::min(0.0, below));
    const double lowB = wb * (1.0 - shock * std::max(0.0, below));
    // An immovable upper ball on a movable lower one (lowA + lowB = 0): the
    // lower one moves, by the plain share below.
    if (lowA + lowB > 0.0) {
      const Vec2 along = (overlap * below) * s.down;  // the move along gravity
      const Vec2 across = overlap * n - along;
      const double even = 1.0 / (wa + wb), low = 1.0 / (lowA + lowB);
      xa -= (wa * even) * across + (lowA * low) * along;
      xb += (wb * even) * across + (lowB * low) * along;
      return overlap;
    }
  }
  const double share = overlap / (wa + wb);
  xa -= share * wa * n;
  xb += share * wb * n;
  return overlap;
}

}  // namespace

void ScaleSolver::reset() {
  lastNumberOf_.clear();
  numberOf_.clear();
  settled_ = false;
}

std::size_t ScaleSolver::memoryBytes() const {
  std::size_t bytes =
      sizeof(Row) * rows_.capacity() + sizeof(Pair) * pairs_.capacity() +
      sizeof(double) * (bounce_.capacity() + invMass_.capacity()) +
      sizeof(double) * (separation_.capacity() + totalN_.capacity() + totalT_.capacity()) +
      sizeof(Moved) * moved_.capacity() + sizeof(Motion) * motion_.capacity() +
      sizeof(int) * (blockStart_.capacity() + blockCount_.capacity()) +
      sizeof(int) * (ballBlockStart_.capacity() + ballBlockCount_.capacity()) +
      sizeof(int) * (bandOf_.capacity() + stripOfColumn_.capacity() + bandOfRow_.capacity()) +
      sizeof(Vec2) * forceShare_.capacity() +
      sizeof(int) * (lastStart_.capacity() + lastOther_.capacity() + lastOf_.capacity()) +
      sizeof(int) * stripOf_.capacity() + sizeof(int) * slot_.capacity() +
      sizeof(int) * (slotOf_.capacity() + slotCount_.capacity()) +
      sizeof(std::size_t) * linkStart_.capacity() +
      sizeof(double) * (lastN_.capacity() + lastT_.capacity()) +
      sizeof(int) * (cellStart_.capacity() + ballCell_.capacity() + cellOf_.capacity() +
                     cellCount_.capacity()) +
      sizeof(int) * (numberOf_.capacity() + lastNumberOf_.capacity()) +
      sizeof(CellBall) * cellBalls_.capacity() + sizeof(ThreadLinks) * found_.capacity() +
      sizeof(VelocityBox) * (cellBox_.capacity() + rowBox_.capacity()) +
      sizeof(double) * fastReach_.capacity() + sizeof(int) * movedIn_.capacity() +
      sizeof(int) * impactNode_.capacity();
  for (const ThreadLinks& f : found_) bytes += sizeof(Link) * f.links.capacity();
  for (const ThreadRows& r : impactRows_) bytes += sizeof(int) * r.rows.capacity();
  return bytes;
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
  const bool banded = static_cast<long long>(n) >= settings.scaleBandsFrom;
  const int substeps = std::max(0, settings.scaleSubsteps);
  const bool soft = substeps > 0;
  findRows(s, pool, settings.scaleFastPairCells, banded ? settings.scaleBandRows : 0, soft);

  const int iterations = std::max(1, settings.scaleVelocityIterations);
  const int passes = std::max(1, settings.scalePositionPasses);
  // Below 1 it would be under-relaxation, from 2 on Gauss-Seidel diverges;
  // with too few iterations to undo its overshoot it erupts a deep pile
  // (SolverSettings::scaleOverRelaxationFrom).
  const double relax =
      iterations >= settings.scaleOverRelaxationFrom && std::isfinite(settings.scaleOverRelaxation)
          ? std::clamp(settings.scaleOverRelaxation, 1.0, 1.99)
          : 1.0;
  const double shock = std::clamp(settings.scaleShockPropagation, 0.0, 1.0);
  // Without gravity there is no "upper" ball: no support sweep.
  // Nor in the soft step, whose impulses carry the weight.
  const bool supportSweep = !soft && settings.scaleVelocityShock && s.down.squaredNorm() > 0.0;
  // The settle iteration repairs what the support sweep did, once the pile
  // has settled (SolverSettings::scaleSettleIteration; settled_ says when).
  const bool settleCheck = supportSweep && settings.scaleSettleIteration;
  const bool settle = settleCheck && settled_;
  // Without walls there is nothing to guard against.
  const bool guard = !s.walls.empty();
  // Impacts in sequence (SolverSettings::scaleSequentialImpacts): the
  // restitution pass notes the rows that pushed in this step; one thread
  // replays the groups of impacts after the passes.
  const bool sequential = settings.scaleSequentialImpacts && !soft;
  if (sequential) {
    impactRows_.resize(static_cast<std::size_t>(threads));
    for (ThreadRows& r : impactRows_) r.rows.clear();
  }
  // What each thread saw of the overlap, written once per row: one cache
  // line per thread, or the two threads fight over one line on every row
  // (measured: 2 threads gained 1.07x at N = 10,000 with them side by side).
  struct alignas(64) Seen {
    double deepest = 0.0;
    std::array<char, 2> moved{0, 0};
  };
  std::vector<Seen> seen(static_cast<std::size_t>(threads));
  int passesUsed = 0;

  // Runs f on every row, in the order of the Gauss-Seidel sweep: band by
  // band from the bottom (bands_ of SolverSettings::scaleBandRows grid rows;
  // docs/scale.md, "Bands"), and within a band the even strips, then the odd
  // ones; each strip's rows of the band in (a, b) order. A row touches the
  // balls of its own strip and the next, so two strips of one parity share no
  // ball and the threads share them. Thread t takes a block of neighbouring
  // strips (the same block in every band), and only its border strips, whose
  // rows touch balls of another thread's strips, are ordered against that
  // thread: before a border strip's rows of phase p (a band and a parity) the
  // thread waits until its neighbour has done its border rows of every phase
  // before p, and it announces p + 1 as soon as its own are done. A barrier
  // after every band and parity instead made two threads 14 % slower at
  // N = 10,000. The order of the operations on every ball is the same for
  // any thread count, and so is every bit of the result.
  const int strips = strips_, bands = bands_;
  const auto ownerOf = [&](int st) {
    const int count = (strips - st % 2 + 1) / 2;
    return st / 2 * threads / count;
  };
  // Per strip: its thread, and the threads whose strips its rows touch or
  // whose rows touch its balls (-1: none).
  std::array<int, kMaxStrips> owner{}, left{}, right{};
  for (int st = 0; st < strips; ++st) owner[static_cast<std::size_t>(st)] = ownerOf(st);
  for (int st = 0; st < strips; ++st) {
    const auto i = static_cast<std::size_t>(st);
    left[i] = st > 0 && owner[i - 1] != owner[i] ? owner[i - 1] : -1;
    right[i] = st + 1 < strips && owner[i + 1] != owner[i] ? owner[i + 1] : -1;
  }
  pool.resetProgress();
  // A thread takes its strips of one phase interleaved, row by row in turn
  // (strip 0's first row, strip 2's first row, ..., strip 0's second row,
  // ...): the strips share no ball, so the result is bit for bit that of
  // solving them one after another, but consecutive rows no longer wait for
  // each other. Within a strip each row waits for the last one that touched
  // its balls ((a, b) order puts a ball's rows side by side), so one strip at
  // a time leaves the core idle on that chain of loads and stores. At most
  // kInterleave strips at a time, though: at N = 100,000 (16 strips of a
  // parity on one thread) stage timers gave the iterations 15-20 % less time
  // taking them 8 by 8 than all 16 at once (fewer streams of rows and balls
  // for the prefetchers), but whole-step A/B pairs were within the host's
  // noise; at N = 10,000 (7 strips) nothing changes. Same bits either way.
  // One phase: the rows of one band and parity.
  // `starts` is blockStart_ for the rows; the soft step's ball passes take
  // its balls block by block in the same way (ballBlockStart_).
  auto phaseOver = [&](const int* starts, int t, int phase, int band, int parity, auto&& f) {
    std::array<std::size_t, kMaxStrips> from{}, to{};
    int inner = 0, borders = 0;
    // The border strips first (at most two, so in the first group of
    // kInterleave), each after its neighbours' waits, and interleaved with
    // the inner strips: on their own, their rows waited on each other, and
    // at N = 10,000 on two threads a border strip is one of a thread's three
    // strips of a parity. Interleaved, the 10,000 pile's step was 3-8 %
    // faster on two threads in three A/B pairs; at 100,000 (one of eight)
    // no difference showed (docs/scale.md, "Two rows to a loop body").
    // Same bits: only rows of strips that share no ball change places.
    for (const bool borderPass : {true, false})
      for (int st = parity; st < strips; st += 2) {
        const auto i = static_cast<std::size_t>(st);
        const bool border = left[i] >= 0 || right[i] >= 0;
        if (owner[i] != t || border != borderPass) continue;
        if (left[i] >= 0) pool.waitFor(left[i], phase);
        if (right[i] >= 0) pool.waitFor(right[i], phase);
        const std::size_t block =
            i * static_cast<std::size_t>(bands) + static_cast<std::size_t>(band);
        const auto b = static_cast<std::size_t>(starts[block]);
        const auto e = static_cast<std::size_t>(starts[block + 1]);
        if (b == e) continue;
        from[static_cast<std::size_t>(inner)] = b;
        to[static_cast<std::size_t>(inner)] = e;
        ++inner;
        if (border) ++borders;
      }
    // The neighbour may go on once the border strips are done: now if there
    // are none, else when the last of them ends (below).
    if (threads > 1 && borders == 0) pool.announce(t, phase + 1);
    for (int g = 0; g < inner; g += kInterleave) {
      std::array<std::size_t, kInterleave> at{}, end{};
      std::array<bool, kInterleave> border{};
      int active = 0;
      for (int u = g; u < std::min(inner, g + kInterleave); ++u, ++active) {
        at[static_cast<std::size_t>(active)] = from[static_cast<std::size_t>(u)];
        end[static_cast<std::size_t>(active)] = to[static_cast<std::size_t>(u)];
        border[static_cast<std::size_t>(active)] = u < borders;
      }
      while (active > 0) {
        // As many rounds as the shortest strip has rows left: no strip ends
        // within them, so no row pays a test of its strip's end; and two
        // strips' rows to a loop body. Together, in alternating A/B runs on
        // one thread, 0-6 % faster at N = 10,000 (median 3 %) and 3-5 % at
        // 100,000; the rounds alone, one row to a body, gained about 1 %, and
        // four rows to a body lost 7 % (docs/scale.md, "Two rows to a loop
        // body"). Same bits: each strip's rows keep their order.
        std::size_t rounds = end[0] - at[0];
        for (int j = 1; j < active; ++j) {
          const auto u = static_cast<std::size_t>(j);
          rounds = std::min(rounds, end[u] - at[u]);
        }
        for (std::size_t round = 0; round < rounds; ++round) {
          int j = 0;
          for (; j + 1 < active; j += 2) {
            const auto u = static_cast<std::size_t>(j);
            const std::size_t k = at[u]++, l = at[u + 1]++;
            f(k);
            f(l);
          }
          if (j < active) f(at[static_cast<std::size_t>(j)]++);
        }
        // The strips that are done leave; the others keep their order.
        int kept = 0;
        for (int j = 0; j < active; ++j) {
          const auto u = static_cast<std::size_t>(j);
          if (at[u] == end[u]) {
            if (border[u] && --borders == 0) pool.announce(t, phase + 1);
            continue;
          }
          at[static_cast<std::size_t>(kept)] = at[u];
          end[static_cast<std::size_t>(kept)] = end[u];
          border[static_cast<std::size_t>(kept)] = border[u];
          ++kept;
        }
        active = kept;
      }
    }
  };
  auto onePhase = [&](int t, int phase, int band, int parity, auto&& f) {
    phaseOver(blockStart_.data(), t, phase, band, parity, f);
  };
  auto byStrip = [&](int t, int& phase, auto&& f) {
    for (int band = 0; band < bands; ++band)
      for (int parity = 0; parity < 2; ++parity, ++phase) onePhase(t, phase, band, parity, f);
  };

  enum class Pass { WarmStart, Relaxed, Plain, Restitution, Support };
  std::vector<Pass> velocityPasses{Pass::WarmStart};
  velocityPasses.insert(velocityPasses.end(), static_cast<std::size_t>(iterations - 1),
                        Pass::Relaxed);
  velocityPasses.push_back(Pass::Plain);
  velocityPasses.push_back(Pass::Restitution);
  if (supportSweep) velocityPasses.push_back(Pass::Support);
  if (settle) velocityPasses.push_back(Pass::Plain);
  // Whole passes, one after another: a front of one band per pass (lag
  // bands_) never has two passes at once.
  const int lag = settings.scaleWavefront ? bandReach_ : bands;

  Motion* m = motion_.data();
  CellBall* ball = cellBalls_.data();
  movedIn_.resize(n);
  int* movedIn = movedIn_.data();

  // The soft step (SolverSettings::scaleSubsteps; docs/scale.md, "The soft
  // step"). Its passes over balls (the forces' share, the move) go strip by
  // strip and band by band like its passes over rows, each thread on its own
  // strips' balls, so that every pass takes part in the wavefront.
  scale::SoftStep softStep;
  // Its passes in order: per substep the forces' share (balls), the warm
  // start (rows), the spring (rows), the move (balls), the relax (rows);
  // then the bounce (rows).
  enum class SoftPass { Forces, WarmStart, Spring, Move, Relax, Bounce };
  std::vector<SoftPass> softPassList;
  const bool forced = !s.forcedVelocity.empty();
  if (soft) {
    softStep.h = s.dt / substeps;
    // At most a quarter of the substep rate, Box2D v3's bound for its soft
    // step (a spring much faster than the substep is no longer resolved by
    // it: past the bound the 10,000 pile jitters instead of coming to rest,
    // docs/scale.md, "The soft step's bound"); walls, which carry the whole
    // pile, get twice the stiffness, as there.
    const double most = softContactHertzMost(s.dt, substeps);
    const double hertz = settings.scaleContactHertz > 0.0
                             ? std::clamp(settings.scaleContactHertz, 1e-3, most)
                             : most;
    const double zeta = std::max(0.0, settings.scaleContactDampingRatio);
    softStep.balls = scale::contactSpring(hertz, zeta, softStep.h);
    softStep.walls = scale::contactSpring(std::min(2.0 * hertz, 2.0 * most), zeta, softStep.h);
    softStep.pushSpeed = std::max(0.0, settings.scaleContactPushSpeed);
    moved_.resize(motion_.size());
    if (forced) forceShare_.resize(motion_.size());
    for (int u = 0; u < substeps; ++u) {
      if (forced) softPassList.push_back(SoftPass::Forces);
      softPassList.insert(softPassList.end(),
                          {SoftPass::WarmStart, SoftPass::Spring, SoftPass::Move, SoftPass::Relax});
    }
    softPassList.push_back(SoftPass::Bounce);
    totalN_.assign(rows_.size(), 0.0);
    totalT_.assign(rows_.size(), 0.0);
  }
  const auto softPasses = [&](int t, std::size_t b, std::size_t e, int& phase) {
    Moved* mv = moved_.data();
    Vec2* force = forceShare_.data();
    const double share = 1.0 / substeps;
    // The World added this step's forces whole; they are added again a
    // substep's share at a time.
    for (std::size_t k = b; k < e; ++k) {
      const auto slot = static_cast<std::size_t>(slotOf_[k]);
      mv[slot] = Moved{};
      if (forced) {
        const Vec2 f = s.forcedVelocity[static_cast<std::size_t>(ball[k].index)];
        m[slot].velocity -= f;
        force[slot] = share * f;
      }
    }
    pool.sync();  // the rows read every ball's move, and other threads' rows touch these balls
    const auto softRow = [&]<bool kSpring>(std::size_t k) {
      Row& r = rows_[k];
      Motion* other = r.b >= 0 ? &m[r.b] : nullptr;
      const Vec2 movedB = r.b >= 0 ? mv[r.b].by : Vec2::Zero();
      const double gap = separation_[k] + (movedB - mv[r.a].by).dot(r.normal());
      scale::softRow<kSpring>(m[r.a], other, r, gap, softStep);
    };
    // Each pass, rows or balls, block by block like the rigid step's
    // passes; a ball pass on a strip whose balls another thread's rows touch
    // waits for that thread's earlier phases as a row pass does, so no pass
    // needs a barrier.
    const auto onePass = [&](SoftPass pass, int phase, int band, int parity) {
      const int* balls = ballBlockStart_.data();
      switch (pass) {
        case SoftPass::Forces:
          return phaseOver(balls, t, phase, band, parity,
                           [&](std::size_t k) { m[k].velocity += force[k]; });
        case SoftPass::WarmStart:
          return onePhase(t, phase, band, parity,
                          [&](std::size_t k) { warmStartRow(m, rows_[k]); });
        case SoftPass::Spring:
          return onePhase(t, phase, band, parity,
                          [&](std::size_t k) { softRow.template operator()<true>(k); });
        case SoftPass::Move:
          return phaseOver(balls, t, phase, band, parity, [&](std::size_t k) {
            mv[k].by += softStep.h * m[k].velocity;
            mv[k].turned += softStep.h * m[k].angularVelocity;
          });
        case SoftPass::Relax:
          // The spring's push taken out of the velocities; what each row
          // gave in this substep is its impulse now (the warm start gave the
          // last substep's, the updates the rest).
          return onePhase(t, phase, band, parity, [&](std::size_t k) {
            softRow.template operator()<false>(k);
            totalN_[k] += rows_[k].lambdaN;
            totalT_[k] += rows_[k].lambdaT;
          });
        case SoftPass::Bounce:
          // -e times the approach the bodies brought into the step (the
          // rigid step's target of a touching row, bounce_ of a speculative
          // one), for the rows that pushed.
          return onePhase(t, phase, band, parity, [&](std::size_t k) {
            Row& r = rows_[k];
            const double bounce = bounce_[k] > 0.0 ? bounce_[k] : std::max(0.0, r.target);
            if (bounce <= 0.0 || totalN_[k] <= 0.0) return;
            const RowChange c = raiseNormalTo(m, r, bounce);
            totalN_[k] += c.normal;
            totalT_[k] += c.tangent;
          });
      }
    };
    // Each substep's passes as a wavefront, as the rigid step's passes (its
    // comment below): a ball and the rows that touch it lie at most
    // bandReach_ bands apart, so a lag of bandReach_ between passes keeps
    // every ball's operations in the order of whole passes, for the same
    // bits. One front for all the step's passes would be as valid, but its
    // passes would spread over the whole pile: at any moment they would
    // touch bands bandReach_ apart up to lag x 5k, and a band would leave
    // the cache between one pass and the next.
    for (std::size_t from = 0; from < softPassList.size();) {
      std::size_t to = from + 1;
      while (to < softPassList.size() && softPassList[to] != softPassList[from]) ++to;
      const int count = static_cast<int>(to - from);
      for (int front = 0; front < bands + lag * (count - 1); ++front)
        for (int p = 0; p < count; ++p) {
          const int band = front - lag * p;
          if (band < 0 || band >= bands) continue;
          for (int parity = 0; parity < 2; ++parity, ++phase)
            onePass(softPassList[from + static_cast<std::size_t>(p)], phase, band, parity);
        }
      from = to;
    }
    pool.sync();
    // The balls took their substeps' moves; one that moved past the rows'
    // margin may have met a wall it has no row with, and is moved again
    // with the wall guard, at the mean velocity of its moves.
    for (std::size_t k = b; k < e; ++k) {
      const auto slot = static_cast<std::size_t>(slotOf_[k]);
      const Vec2 by = mv[slot].by;
      if (guard && movesPastTheMargin(by / s.dt, ball[k].radius, s.dt)) {
        Motion path = m[slot];
        path.velocity = by / s.dt;
        if (moveGuarded(ball[k], path, s)) {
          m[slot].velocity = path.velocity;
          m[slot].angularVelocity = path.angularVelocity;
        }
      } else {
        ball[k].position += by;
      }
    }
    pool.sync();
    // The deepest overlap, measured only: the springs hold it.
    double& deepest = seen[static_cast<std::size_t>(t)].deepest;
    const auto [rb, re] = part(pairs_.size(), t, threads);
    for (std::size_t k = rb; k < re; ++k) {
      WallHit hit;
      double dist = 0.0;
      deepest = std::max(deepest, overlapOf(ball, s, pairs_[k], hit, dist));
    }
  };
  pool.run([&](int t) {
    const auto [b, e] = part(n, t, threads);
    int phase = 0;  // phases so far (passes, bands, parities): the same count on every thread
    if (soft) {
      softPasses(t, b, e, phase);
    } else {
      // The velocity passes, in order: the warm start (the last step's
      // impulses, applied again), the iterations, restitution, the support
      // sweep and the settle iteration (the sweep changed velocities along
      // normals only, with no impulse to show for it: a plain iteration gives
      // the rows back their friction and impulses, the next step's warm start).
      const auto velocityPass = [&](Pass pass, int phase, int band, int parity) {
        switch (pass) {
          case Pass::WarmStart:
            return onePhase(t, phase, band, parity,
                            [&](std::size_t k) { warmStartRow(m, rows_[k]); });
          case Pass::Relaxed:
            return onePhase(t, phase, band, parity,
                            [&](std::size_t k) { solveRow<false>(m, rows_[k], relax); });
          case Pass::Plain:
            return onePhase(t, phase, band, parity,
                            [&](std::size_t k) { solveRow<true>(m, rows_[k], 1.0); });
          case Pass::Restitution:
            return onePhase(t, phase, band, parity, [&](std::size_t k) {
              // A row took part in the step's impacts if it pushed before or
              // after its bounce: one whose balls another impact already
              // sends apart faster than its bounce gives its impulse back
              // here. By default only the rows that bounce are read.
              const Row& r = rows_[k];
              const bool pushed = sequential && r.lambdaN > 0.0;
              if (bounce_[k] > 0.0) restituteRow(m, rows_[k], bounce_[k]);
              if (sequential && (pushed || r.lambdaN > 0.0 || r.lambdaT != 0.0))
                impactRows_[static_cast<std::size_t>(t)].rows.push_back(static_cast<int>(k));
            });
          case Pass::Support:
            return onePhase(t, phase, band, parity,
                            [&](std::size_t k) { supportRow(m, rows_[k], s.down, s.gravityStep); });
        }
      };
      // As a wavefront (SolverSettings::scaleWavefront): pass p on band j
      // follows pass p - 1 on band j + lag (at the same front, the earlier pass
      // first). Rows more than bandReach_ bands apart share no ball, so with
      // that lag every ball meets its rows in the order of whole passes, one
      // after another, and gets the same bits; but the front holds about
      // lag x passes bands, which stay in cache, where whole passes stream
      // every row through memory once each. A lag of bands_ (scaleWavefront
      // off) is the order of whole passes.
      const int count = static_cast<int>(velocityPasses.size());
      for (int front = 0; front < bands + lag * (count - 1); ++front)
        for (int p = 0; p < count; ++p) {
          const int band = front - lag * p;
          if (band < 0 || band >= bands) continue;
          for (int parity = 0; parity < 2; ++parity, ++phase)
            velocityPass(velocityPasses[static_cast<std::size_t>(p)], phase, band, parity);
        }
      pool.sync();  // every velocity is final before any ball moves
      if (sequential) {
        if (t == 0) replayImpacts(s);
        pool.sync();
      }

      for (std::size_t k = b; k < e; ++k) {
        movedIn[k] = -1;
        Motion& mk = m[slotOf_[k]];
        if (guard && movesPastTheMargin(mk.velocity, ball[k].radius, s.dt))
          moveGuarded(ball[k], mk, s);
        else
          ball[k].position += s.dt * mk.velocity;
      }
      pool.sync();

      double& deepest = seen[static_cast<std::size_t>(t)].deepest;
      for (int pass = 0; pass < passes; ++pass) {
        char& mine = seen[static_cast<std::size_t>(t)].moved[static_cast<std::size_t>(pass % 2)];
        mine = 0;
        byStrip(t, phase, [&](std::size_t k) {
          const Pair& r = pairs_[k];
          // A row whose balls no pass moved since it last looked finds them
          // where it left them, overlapping by no more than its tolerance (it
          // would have moved them otherwise): it would do nothing again. So
          // from the second pass on only the rows beside a move are looked
          // at, for the same bits as looking at them all.
          const int since = pass - 1;
          if (movedIn[r.a] < since && (r.b < 0 || movedIn[r.b] < since)) return;
          const double overlap = projectRow(ball, invMass_.data(), s, r, shock);
          if (pass == 0) deepest = std::max(deepest, overlap);
          if (overlap > kOverlapTolerance * r.reach) {
            mine = 1;
            movedIn[r.a] = pass;
            if (r.b >= 0) movedIn[r.b] = pass;
          }
        });
        pool.sync();  // every thread's flags of this pass are written
        bool any = false;
        for (const Seen& m : seen) any = any || m.moved[static_cast<std::size_t>(pass % 2)] != 0;
        if (t == 0 && any) passesUsed = pass + 1;
        // No barrier before the next pass: it writes the other flags, and the
        // pass after it cannot start before every thread has read these (it
        // waits at the barrier above in between).
        if (!any) break;
      }
    }

    // Back to the scene's numbering. No thread moves a ball any more: the
    // last pass ended with a sync, and every thread left the loop after it.
    for (std::size_t k = b; k < e; ++k) {
      const std::size_t i = static_cast<std::size_t>(ball[k].index);
      const Motion& mk = m[slotOf_[k]];
      s.position[i] = ball[k].position;
      s.velocity[i] = mk.velocity;
      s.angularVelocity[i] = mk.angularVelocity;
      if (s.spin) s.angle[i] += soft ? moved_[slotOf_[k]].turned : s.dt * mk.angularVelocity;
    }
  });

  // Keep this step's impulses for the next step's warm start, by ball a in
  // this step's numbering (slot_ lists the rows in (a, b) order; thread t
  // found the rows of its own range of balls).
  lastOther_.resize(slot_.size());
  lastN_.resize(slot_.size());
  lastT_.resize(slot_.size());
  lastStart_.resize(n + 1);
  pool.run([&](int t) {
    const auto [b, e] = part(n, t, threads);
    std::size_t k = linkStart_[static_cast<std::size_t>(t)];
    const std::size_t stop = linkStart_[static_cast<std::size_t>(t) + 1];
    for (std::size_t a = b; a < e; ++a) {
      lastStart_[a] = static_cast<int>(k);
      for (; k < stop; ++k) {
        // The pair's balls in cell order, the row's impulses.
        const Pair& p = pairs_[static_cast<std::size_t>(slot_[k])];
        const Row& r = rows_[static_cast<std::size_t>(slot_[k])];
        if (static_cast<std::size_t>(p.a) != a) break;
        lastOther_[k] = p.b >= 0 ? p.b : static_cast<int>(n) + (-1 - p.b);
        lastN_[k] = r.lambdaN;
        lastT_[k] = r.lambdaT;
      }
    }
    if (t == threads - 1) lastStart_[n] = static_cast<int>(slot_.size());
  });
  if (impacts) {
    // In the scene's numbering, with a < b and in (a, b) order, as the small
    // path reports them: swapping a and b turns the normal around and leaves
    // both impulses as they are.
    impacts->clear();
    for (std::size_t k = 0; k < slot_.size(); ++k) {
      const auto row = static_cast<std::size_t>(slot_[k]);
      const Row& r = rows_[row];
      const Pair& p = pairs_[row];
      // The soft step's rows hold one substep's impulses; the step's are
      // their sums.
      const double ln = soft ? totalN_[row] : r.lambdaN, lt = soft ? totalT_[row] : r.lambdaT;
      if (ln == 0.0) continue;
      const bool wall = r.b < 0;
      ImpactEvent e{ball[p.a].index,
                    wall ? -1 - r.b : ball[p.b].index,
                    wall,
                    r.normal(),
                    ln,
                    lt,
                    r.friction == 0.0 ? 0.0 : r.friction * ln};
      if (!wall && e.b < e.a) {
        std::swap(e.a, e.b);
        e.normal = -e.normal;
      }
      impacts->push_back(e);
    }
    std::sort(impacts->begin(), impacts->end(), [](const ImpactEvent& x, const ImpactEvent& y) {
      return std::tuple(x.a, x.wall, x.b) < std::tuple(y.a, y.wall, y.b);
    });
  }
  if (settleCheck) {
    // Settled: the balls' mean squared speed below (|g| dt)^2, what gravity
    // adds in one step. Summed on one thread in the scene's order, so that
    // the decision, like every bit of the step, does not depend on the
    // thread count (0.7 ms for a million balls, whose step takes 200-480 ms).
    double speed2 = 0.0;
    for (const Vec2& v : s.velocity) speed2 += v.squaredNorm();
    settled_ = speed2 < static_cast<double>(n) * s.gravityStep * s.gravityStep;
  }
  stats.contacts = static_cast<int>(rows_.size());
  stats.passes = soft ? 2 * substeps : iterations + (settle ? 1 : 0);
  stats.correctionPasses = passesUsed;
  stats.sequentialGroups = sequential ? replayedGroups_ : 0;
  stats.sequentialGroupsLeft = sequential ? leftGroups_ : 0;
  double deepest = 0.0;
  for (const Seen& m : seen) deepest = std::max(deepest, m.deepest);
  stats.maxOverlap = deepest;
}

}  // namespace particles
