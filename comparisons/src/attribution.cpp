#include "particles/compare/attribution.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <sstream>

#include "particles/compare/invariants.h"
#include "particles/reference/box2d_range.h"

namespace particles::compare {
namespace {

// Box2D's recommended iteration count is 8; this many is converged for
// every case of the suite (a few contacts at most).
constexpr int kConvergedIterations = 100;

bool agrees(const ImpactCase& c, const Outcome& x, const Outcome& y) {
  return measureDiscrepancy(c, x, y).relative <= kBox2DTolerance;
}

std::string describe(const char* what, double before, double after) {
  std::ostringstream s;
  s << what << ": discrepancy " << before << " -> " << after;
  return s.str();
}

}  // namespace

std::string_view causeName(Cause c) {
  switch (c) {
    case Cause::Agrees:
      return "agrees";
    case Cause::OutsideRange:
      return "outside Box2D's range";
    case Cause::VelocityIterations:
      return "too few velocity iterations";
    case Cause::RestitutionThreshold:
      return "restitution threshold";
    case Cause::MidOverlapContact:
      return "contact point at the middle of the overlap";
    case Cause::SequentialOrder:
      return "order of sequential impulses";
    case Cause::FloatRounding:
      return "float rounding";
    case Cause::Unexplained:
      return "unexplained";
  }
  return "unknown";
}

Discrepancy measureDiscrepancy(const ImpactCase& c, const Outcome& x, const Outcome& y) {
  Discrepancy d;
  double scale = 1e-300, worst = 0.0;
  for (std::size_t i = 0; i < c.scene.balls.size(); ++i) {
    const BallDef& b = c.scene.balls[i];
    scale = std::max(scale, b.velocity.norm() + std::abs(b.angularVelocity) * b.radius);
    const double dv = (x.balls[i].velocity - y.balls[i].velocity).norm();
    const double dw = std::abs(x.balls[i].angularVelocity - y.balls[i].angularVelocity);
    d.velocity = std::max(d.velocity, dv);
    d.spin = std::max(d.spin, dw);
    worst = std::max({worst, dv, dw * b.radius});
  }
  // NaN in either answer must never read as agreement.
  d.relative = (x.finite && y.finite) ? worst / scale : std::numeric_limits<double>::infinity();
  return d;
}

double floatRoundingBound(const ImpactCase& c, const Outcome&, const Outcome&) {
  double mMin = INFINITY, mMax = 0.0, qMin = INFINITY, qMax = 0.0;
  for (const BallDef& b : c.scene.balls) {
    mMin = std::min(mMin, b.mass);
    mMax = std::max(mMax, b.mass);
    const double q = b.resolvedInertia() / (b.mass * b.radius * b.radius);
    qMin = std::min(qMin, q);
    qMax = std::max(qMax, q);
  }
  const double conditioning = (mMax / mMin) * (qMax / qMin);
  return 64.0 * FLT_EPSILON * std::max(1.0, conditioning);
}

Attribution attributeBox2D(const ImpactCase& c, const Outcome& ref, const Outcome& box2d,
                           const reference::Box2DSettings& settings) {
  Attribution a;
  a.discrepancy = measureDiscrepancy(c, ref, box2d);
  const double d = a.discrepancy.relative;
  if (d <= kBox2DTolerance) return a;

  // Settings first: re-running with more iterations reproduces the cause
  // exactly, where the range check below would only flag the setting.
  if (settings.velocityIterations < kConvergedIterations) {
    reference::Box2DSettings more = settings;
    more.velocityIterations = kConvergedIterations;
    const Outcome converged = runBox2D(c, more);
    if (agrees(c, ref, converged)) {
      a.cause = Cause::VelocityIterations;
      a.detail = describe("with 100 velocity iterations", d,
                          measureDiscrepancy(c, ref, converged).relative);
      return a;
    }
  }
  const auto range = reference::checkBox2DRange(c.scene, settings);
  if (!range.empty()) {
    a.cause = Cause::OutsideRange;
    a.detail = range.front().message;
    return a;
  }
  if (settings.restitutionThreshold > 0.0) {
    if (const auto noBounce = runTruthNoBounce(c); noBounce && agrees(c, *noBounce, box2d)) {
      a.cause = Cause::RestitutionThreshold;
      a.detail =
          "Box2D matches the closed form with e = 0: the approach was slower than its "
          "restitution threshold";
      return a;
    }
  }
  // Only when moving the contact point changes the answer measurably: a tiny
  // overlap moves it by far less than float resolution.
  if (const auto mid = runTruthMidOverlap(c);
      mid && !agrees(c, ref, *mid) && agrees(c, *mid, box2d)) {
    a.cause = Cause::MidOverlapContact;
    a.detail = describe("closed form with lever arms r - overlap/2", d,
                        measureDiscrepancy(c, *mid, box2d).relative);
    return a;
  }
  if (!c.isolated &&
      violatedInvariants(measureInvariants(c, box2d), toleranceFor(Source::Box2D)).empty()) {
    a.cause = Cause::SequentialOrder;
    a.detail =
        "several simultaneous contacts; both answers conserve momentum and lose energy, "
        "Box2D solves the contacts together, the engine one exchange at a time";
    return a;
  }
  const double bound = floatRoundingBound(c, initialState(c), ref);
  if (d <= bound) {
    a.cause = Cause::FloatRounding;
    std::ostringstream s;
    s << "discrepancy " << d << " within the float bound " << bound << " for this case";
    a.detail = s.str();
    return a;
  }
  a.cause = Cause::Unexplained;
  std::ostringstream s;
  s << "discrepancy " << d << "; no cause reproduces Box2D's answer";
  a.detail = s.str();
  return a;
}

}  // namespace particles::compare
