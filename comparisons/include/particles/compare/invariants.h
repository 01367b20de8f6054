// Invariant residuals of one source's answer to a case: the checks of
// docs/physics.md, computed from velocities alone so that they apply to
// Box2D as well as to the engine and the closed form.
#pragma once

#include "particles/compare/outcome.h"

namespace particles::compare {

// Every residual is dimensionless: divided by the case's momentum, angular
// momentum, energy or speed scale. NaN means "does not apply to this case".
struct Invariants {
  double momentum = 0.0;         // |change of total linear momentum| (no walls only)
  double angularMomentum = 0.0;  // isolated: max over balls of |change of L about the contact
                                 // point|; otherwise (no walls) the total about the origin
  double energyChange = 0.0;     // (E' - E) / E; must be <= 0
  double restitution = 0.0;      // isolated: |gn' + e gn| / |gn|
  double noSlip = 0.0;           // isolated, mu infinite: |gt'| / speed scale
  double coulomb = 0.0;          // isolated, finite mu: max(0, |lambdaT| - mu lambdaN) / lambdaN
  double tangentSign = 0.0;      // isolated, mu > 0: lambdaT against the slip: 0 ok, 1 wrong sign
  // The part of `angularMomentum` the model itself allows in a multi-contact
  // case: the lever arms are the radii, so across an overlap d a pair's two
  // impulses act at points d apart and leave d |lambdaT| of angular momentum
  // about any fixed point. Bounded by (largest overlap / smallest radius)
  // times the momentum scale; 0 in isolated cases, where each ball is
  // measured about its own contact point.
  double angularMomentumSlack = 0.0;
  double normalImpulse = 0.0;   // isolated, approaching: lambdaN (N s), for the record
  double tangentImpulse = 0.0;  // isolated: lambdaT (N s), for the record
};

Invariants measureInvariants(const ImpactCase& c, const Outcome& after);

// Tolerances an answer's residuals must meet, per source precision.
struct InvariantTolerance {
  double conservation;  // momentum, angular momentum, restitution, no-slip, Coulomb
  double energyGrowth;  // allowed relative energy increase (rounding only)
};
InvariantTolerance toleranceFor(Source s);

// Names of the invariants the answer breaks under the tolerance; empty if none.
std::vector<std::string> violatedInvariants(const Invariants& inv, const InvariantTolerance& tol);

}  // namespace particles::compare
