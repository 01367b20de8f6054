// The soft step's row updates (SolverSettings::scaleSubsteps; docs/scale.md,
// "The soft step"), and the friction update it shares with the rigid step.
// Internal to the large-scene path.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include "particles/scale_solver.h"

namespace particles::scale {

// The Coulomb bound of a row's accumulated friction impulse, mu lambdaN.
// For mu = infinity (no-slip) it is the limit of mu lambdaN: none while the
// row pushes, 0 while it does not (a contact that exchanges no normal
// impulse cannot grip, and inf * 0 would be NaN). Without that 0, a row
// whose normal impulse the passes gave back kept gripping: in a no-slip gas
// 38 % of the disks' spin changes were explained by no impact
// (docs/scale.md, "The rough gas").
inline double frictionBound(const ScaleSolver::Row& r) {
  if (std::isinf(r.friction)) return r.lambdaN > 0.0 ? r.friction : 0.0;
  return r.friction * r.lambdaN;
}

// The change of a row's accumulated friction impulse that cancels the
// tangential relative velocity gt, clamped to the Coulomb bound; the row
// keeps the new total.
inline double frictionChange(ScaleSolver::Row& r, double gt) {
  double lt = r.lambdaT - gt * r.massT;
  const double bound = frictionBound(r);
  lt = std::clamp(lt, -bound, bound);
  const double dt = lt - r.lambdaT;
  r.lambdaT = lt;
  return dt;
}

// A contact spring of `hertz` and damping ratio `zeta`, solved implicitly
// over a substep of h seconds, as three numbers for the velocity update.
// The spring-damper k = m w^2, c = 2 zeta m w (w = 2 pi hertz) on overlap
// x, integrated implicitly over h, asks the normal velocity to reach
// -biasRate x while the impulse found is scaled by massScale and the impulse
// already accumulated leaks away by impulseScale:
//   a1 = 2 zeta + h w, a2 = h w a1, biasRate = w / a1,
//   massScale = a2 / (1 + a2), impulseScale = 1 / (1 + a2)
// (derived in docs/scale.md, "The soft step"; the same constants as Erin
// Catto's "Solver2D" soft step). The rigid limit (hertz -> inf) is
// massScale 1, impulseScale 0, biasRate 1/h: close the overlap in one substep.
struct ContactSpring {
  double biasRate = 0.0;      // 1/s
  double massScale = 1.0;     // dimensionless
  double impulseScale = 0.0;  // dimensionless
};

inline ContactSpring contactSpring(double hertz, double zeta, double h) {
  const double w = 2.0 * std::numbers::pi * hertz;
  const double a1 = 2.0 * zeta + h * w;
  const double a2 = h * w * a1;
  return {w / a1, a2 / (1.0 + a2), 1.0 / (1.0 + a2)};
}

// The soft step's constants for one step: the springs of ball pairs and of
// walls, the substep, the push bound.
struct SoftStep {
  ContactSpring balls, walls;
  double h = 0.0;          // s, the substep
  double pushSpeed = 0.0;  // m/s
};

// One update of a row in the soft step: the normal impulse (kSpring: against
// the spring on the overlap; without it, the relax pass, only against
// approach), then the friction, bounded by mu times the normal impulse it
// now has. A gap still open (s > 0) may close within the substep, never
// more. `gap` is the row's gap now (m): its gap at the start of the step
// plus how the balls moved since along n.
template <bool kSpring>
inline void softRow(ScaleSolver::Motion& a, ScaleSolver::Motion* b, ScaleSolver::Row& r, double gap,
                    const SoftStep& soft) {
  const Vec2 n = r.normal(), tau = perpLeft(n);
  Vec2 va = a.velocity, vb = b ? b->velocity : Vec2::Zero();
  double wa = a.angularVelocity, wb = b ? b->angularVelocity : 0.0;
  const double ib = b ? b->invMass : 0.0, jb = b ? b->invInertia : 0.0, rb = b ? b->radius : 0.0;
  double bias = 0.0, massScale = 1.0, leak = 0.0;
  if (gap > 0.0) {
    bias = gap / soft.h;
  } else if (kSpring) {
    const ContactSpring& spring = b ? soft.balls : soft.walls;
    bias = std::max(spring.biasRate * gap, -soft.pushSpeed);
    massScale = spring.massScale;
    leak = spring.impulseScale;
  }
  const double gn = (vb - va).dot(n);
  // Apart and parting fast enough, with no impulse: nothing to do.
  if (r.lambdaN == 0.0 && r.lambdaT == 0.0 && gn + bias >= 0.0) return;
  const double ln = std::max(0.0, r.lambdaN - r.massN * massScale * (gn + bias) - leak * r.lambdaN);
  const double dn = ln - r.lambdaN;
  r.lambdaN = ln;
  va -= a.invMass * (dn * n);
  vb += ib * (dn * n);
  if (r.friction > 0.0) {
    const double dt = frictionChange(r, (vb - va).dot(tau) - wb * rb - wa * a.radius);
    va -= a.invMass * (dt * tau);
    wa -= a.radius * dt * a.invInertia;
    vb += ib * (dt * tau);
    wb -= rb * dt * jb;
  }
  a.velocity = va;
  a.angularVelocity = wa;
  if (b) {
    b->velocity = vb;
    b->angularVelocity = wb;
  }
}

}  // namespace particles::scale
