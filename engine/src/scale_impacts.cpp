// Impacts in sequence (SolverSettings::scaleSequentialImpacts; docs/scale.md,
// "Impacts in sequence"). The rigid step's velocity passes solve all of a
// step's contacts at once. For one impact that is the handout's impulse to
// rounding, but when a ball meets two others within one step (three balls
// meeting, or an impact passed on to a third ball) one restitution sweep
// cannot give every pair its bounce, and an elastic gas loses energy in
// exactly those steps. Here such a group (and a lone touching impact, which
// the passes may leave off its bounce) is solved again as the small-scene
// step would: pairwise impacts, one after another, each the handout's
// impulse, in the order of their times of impact within the step. Under
// gravity or scene forces a group with a touching row, which may carry a
// load, is left to the passes (replayImpacts says why).
#include <algorithm>
#include <limits>
#include <vector>

#include "particles/contact_impulse.h"
#include "particles/material.h"
#include "particles/scale_solver.h"
#include "scale_common.h"

namespace particles {
namespace {

// At most this many impacts per row of a group: a group of hard disks meets
// a finite number of times, and an inelastic one that would collapse within
// the step stops here with what it has (the overlap removal then separates
// what still approaches, and the next step's rows bounce it).
constexpr std::size_t kMostImpactsPerRow = 16;

int findRoot(std::vector<int>& parent, int x) {
  while (parent[static_cast<std::size_t>(x)] != x) {
    const auto u = static_cast<std::size_t>(x);
    parent[u] = parent[static_cast<std::size_t>(parent[u])];  // path halving
    x = parent[u];
  }
  return x;
}

}  // namespace

void ScaleSolver::replayImpacts(const ScaleBodies& s) {
  replayedGroups_ = 0;
  leftGroups_ = 0;
  std::vector<int> rows;
  for (const ThreadRows& t : impactRows_) rows.insert(rows.end(), t.rows.begin(), t.rows.end());
  if (rows.empty()) return;
  // Row order, whatever thread noted a row: the same groups, replayed in the
  // same order, for any thread count.
  std::sort(rows.begin(), rows.end());

  // The groups: balls joined by the rows that pushed (walls join nothing).
  // Every row that pushed a ball of a group is in the group.
  impactNode_.resize(motion_.size(), -1);
  std::vector<int> parent, ballOfNode;
  const auto node = [&](int ball) {
    int& id = impactNode_[static_cast<std::size_t>(ball)];
    if (id < 0) {
      id = static_cast<int>(parent.size());
      parent.push_back(id);
      ballOfNode.push_back(ball);
    }
    return id;
  };
  for (const int k : rows) {
    const Row& r = rows_[static_cast<std::size_t>(k)];
    const int a = node(r.a);
    if (r.b < 0) continue;
    const int b = node(r.b);
    parent[static_cast<std::size_t>(findRoot(parent, a))] = findRoot(parent, b);
  }
  // Which groups are replayed. A row that was apart at the start of the step
  // (target < 0) is an impact; the restitution pass, the last to touch it,
  // leaves a lone one the handout's impulse exactly. A touching row (target >=
  // 0: its bounce, or 0) has no such last word: a lone one is replayed, as
  // another row's impulse, taken back within the passes, may have moved where
  // its own ended. A group of several rows is replayed if they are all
  // impacts, or if nothing presses balls together: without gravity and scene
  // forces no contact carries a load, and every touching row is an impact
  // too. Otherwise a touching row may carry a load (a pile's contacts, which
  // the warm start holds up and the support sweep moves without impulse), and
  // the group is left to the passes.
  const bool unloaded = s.forcedVelocity.empty();
  std::vector<int> count(parent.size(), 0);
  std::vector<char> touching(parent.size(), 0);
  const auto rootOf = [&](int k) {
    return static_cast<std::size_t>(findRoot(
        parent, impactNode_[static_cast<std::size_t>(rows_[static_cast<std::size_t>(k)].a)]));
  };
  for (const int k : rows) {
    const std::size_t root = rootOf(k);
    ++count[root];
    if (!(rows_[static_cast<std::size_t>(k)].target < 0.0)) touching[root] = 1;
  }
  // Each group's rows in row order; the groups in the order of their first row.
  std::vector<std::vector<int>> groupRows;
  std::vector<int> groupOf(parent.size(), -1);
  for (const int k : rows) {
    const std::size_t root = rootOf(k);
    if (count[root] == 1 && !touching[root]) continue;
    if (count[root] > 1 && touching[root] && !unloaded) {
      if (groupOf[root] == -1) {
        groupOf[root] = -2;  // counted once
        ++leftGroups_;
      }
      continue;
    }
    if (groupOf[root] < 0) {
      groupOf[root] = static_cast<int>(groupRows.size());
      groupRows.emplace_back();
    }
    groupRows[static_cast<std::size_t>(groupOf[root])].push_back(k);
  }
  for (const int ball : ballOfNode) impactNode_[static_cast<std::size_t>(ball)] = -1;
  for (const std::vector<int>& group : groupRows) replayGroup(s, group);
  replayedGroups_ = static_cast<int>(groupRows.size());
}

void ScaleSolver::replayGroup(const ScaleBodies& s, const std::vector<int>& rows) {
  Motion* m = motion_.data();
  // The passes' impulses taken back: the velocities the balls came with.
  // (Under gravity the support sweep, after the restitution pass, may have
  // changed a velocity without an impulse; that change is kept.)
  for (const int k : rows) {
    Row& r = rows_[static_cast<std::size_t>(k)];
    scale::applyRow(m, r, -r.lambdaN, -r.lambdaT);
    r.lambdaN = 0.0;
    r.lambdaT = 0.0;
  }
  const auto body = [&](int slot, int cell) {
    const Motion& b = m[static_cast<std::size_t>(slot)];
    const std::size_t scene =
        static_cast<std::size_t>(cellBalls_[static_cast<std::size_t>(cell)].index);
    return ContactBody{
        b.velocity, b.angularVelocity,
        b.invMass,  b.invInertia,
        b.radius,   s.forcedVelocity.empty() ? Vec2(0.0, 0.0) : s.forcedVelocity[scene]};
  };
  const double inf = std::numeric_limits<double>::infinity();
  for (std::size_t event = 0; event < kMostImpactsPerRow * rows.size(); ++event) {
    // The next impact: the row whose bodies, at their velocities now, close
    // the gap they had at the start of the step soonest within the step (the
    // target of a row apart at the start is -gap / dt; a touching row has no
    // gap). Ties: the lower row.
    // As in the passes, the balls are not moved within the step: the times
    // only order the impacts.
    int next = -1;
    double soonest = inf;
    for (const int k : rows) {
      const Row& r = rows_[static_cast<std::size_t>(k)];
      const Vec2 vb = r.b >= 0 ? m[static_cast<std::size_t>(r.b)].velocity : Vec2::Zero();
      const double gn = (vb - m[static_cast<std::size_t>(r.a)].velocity).dot(r.normal());
      const double gap = std::max(0.0, -r.target * s.dt);
      if (!(gn * s.dt < -gap)) continue;
      const double at = gap / -gn;
      if (at < soonest) {
        soonest = at;
        next = k;
      }
    }
    if (next < 0) break;
    Row& r = rows_[static_cast<std::size_t>(next)];
    const Pair& p = pairs_[static_cast<std::size_t>(next)];
    const ContactMaterial& ma =
        s.material[static_cast<std::size_t>(cellBalls_[static_cast<std::size_t>(p.a)].index)];
    ContactBody a = body(r.a, p.a);
    ContactBody b;
    ContactMaterial mix;
    if (r.b >= 0) {
      b = body(r.b, p.b);
      mix = mixMaterials(
          ma,
          s.material[static_cast<std::size_t>(cellBalls_[static_cast<std::size_t>(p.b)].index)]);
    } else {
      mix = mixMaterials(ma, s.wallMaterial[static_cast<std::size_t>(-1 - r.b)]);
    }
    const ContactImpulse j = resolveImpact(a, b, r.normal(), mix);
    r.lambdaN += j.normal;
    r.lambdaT += j.tangent;
    Motion& ra = m[static_cast<std::size_t>(r.a)];
    ra.velocity = a.velocity;
    ra.angularVelocity = a.angularVelocity;
    if (r.b >= 0) {
      Motion& rb = m[static_cast<std::size_t>(r.b)];
      rb.velocity = b.velocity;
      rb.angularVelocity = b.angularVelocity;
    }
  }
}

}  // namespace particles
