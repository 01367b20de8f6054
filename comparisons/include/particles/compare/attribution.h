// Why Box2D disagrees with the reference answer of a case (the closed form
// where there is one, else the engine). Every discrepancy above tolerance is
// attributed to a named cause, or flagged unexplained: that flag is the point
// of the tool.
#pragma once

#include <string>
#include <string_view>

#include "particles/compare/outcome.h"

namespace particles::compare {

// How two answers to the same case differ.
struct Discrepancy {
  double velocity = 0.0;  // m/s, largest |v_x - v_y| over the balls
  double spin = 0.0;      // rad/s, largest |w_x - w_y| over the balls
  // Dimensionless: the largest of |dv| and |dw| r over the balls, divided by
  // the case's speed scale (largest |v| + |w| r before the impact).
  double relative = 0.0;
};

Discrepancy measureDiscrepancy(const ImpactCase& c, const Outcome& x, const Outcome& y);

enum class Cause {
  Agrees,                // within tolerance: nothing to attribute
  OutsideRange,          // checkBox2DRange flags the case
  VelocityIterations,    // more iterations make Box2D agree
  RestitutionThreshold,  // approach below Box2D's threshold: it did not bounce
  MidOverlapContact,     // Box2D's contact point in the middle of the overlap (lever r - d/2)
  SequentialOrder,       // several contacts: Box2D's simultaneous solution vs sequential exchanges
  FloatRounding,         // within what float arithmetic explains for this case
  Unexplained,
};

std::string_view causeName(Cause c);  // "agrees", "outside Box2D's range", ...

// Relative discrepancy below which two double answers agree.
inline constexpr double kDoubleTolerance = 1e-9;
// Relative discrepancy below which Box2D agrees with a double answer with
// nothing to explain: float resolution (6e-8) times a margin for the handful
// of operations in one step.
inline constexpr double kBox2DTolerance = 1e-5;
// What float rounding can explain in this case: float resolution amplified by
// the case's mass and inertia ratios (the light body's velocity change is
// computed from the heavy one's terms) and by the ratio of the speed scale to
// the velocity change, with a margin.
double floatRoundingBound(const ImpactCase& c, const Outcome& before, const Outcome& reference);

struct Attribution {
  Cause cause = Cause::Agrees;
  Discrepancy discrepancy;  // Box2D against the reference answer
  std::string detail;       // for people: what was checked and found
};

// Box2D's position correction is not among the causes: in Box2D 2.4 the
// position solver moves positions only, so it cannot change the velocities
// of a one-step case. It shows in time-stepped comparisons (`particles
// compare`), as later contacts that start from different overlaps.
//
// Attributes Box2D's answer `box2d` (obtained with `settings`) against the
// reference answer. Re-runs Box2D or the closed form as each cause needs.
Attribution attributeBox2D(const ImpactCase& c, const Outcome& reference, const Outcome& box2d,
                           const reference::Box2DSettings& settings);

}  // namespace particles::compare
