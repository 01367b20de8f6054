#include "particles/compare/attribution.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <sstream>

#include "particles/compare/box2d_model.h"
#include "particles/compare/invariants.h"
#include "particles/reference/box2d_range.h"

namespace particles::compare {
namespace {

// Box2D's recommended iteration count is 8; this many is converged for
// every case of the suite (a few contacts at most).
constexpr int kConvergedIterations = 100;
// Box2D 2.4.1's per-step motion clamps (b2_common.h): b2_maxTranslation
// metres and b2_maxRotation radians per step; a velocity within this fraction
// of one was clamped.
constexpr double kMaxTranslation = 2.0;
constexpr double kMaxRotation = 0.5 * 3.14159265358979323846;
constexpr double kClampFraction = 1.0 - 1e-6;

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

  // Attribution by reproduction: first Box2D's own algorithm, replayed in
  // double, must give Box2D's answer (up to float rounding); then one of its
  // settings at a time is moved to the engine's model, and the one that
  // makes it agree with the reference is the cause.
  Box2DModelSettings model;
  model.velocityIterations = settings.velocityIterations;
  model.restitutionThreshold = settings.restitutionThreshold;
  model.noSlipFriction = settings.noSlipFriction;
  const Outcome replay = runBox2DModel(c, model);
  const double floatBound = std::max(kBox2DTolerance, floatRoundingBound(c, initialState(c), ref));
  const double replayGap = measureDiscrepancy(c, replay, box2d).relative;
  if (!(replayGap <= floatBound)) {
    const auto range = reference::checkBox2DRange(c.scene, settings);
    a.cause = range.empty() ? Cause::Unexplained : Cause::OutsideRange;
    std::ostringstream s;
    s << "Box2D differs from its own algorithm replayed in double by " << replayGap
      << " (float bound " << floatBound << ")";
    if (!range.empty()) s << "; " << range.front().message;
    a.detail = s.str();
    return a;
  }
  const double modelGap = measureDiscrepancy(c, replay, ref).relative;
  if (modelGap <= kBox2DTolerance) {
    a.cause = Cause::FloatRounding;
    a.detail = describe("its algorithm in double agrees with the reference", d, modelGap);
    return a;
  }

  struct Trial {
    Cause cause;
    const char* what;
    Box2DModelSettings settings;
  };
  // Only the settings that can matter for this case are tried: moving the
  // contact point changes lever arms by overlap / 2, which cannot close a gap
  // above tolerance when the overlap is a smaller fraction of the radii; the
  // motion clamps matter only if a velocity reached one.
  double overlapRatio = 0.0;
  const auto& balls = c.scene.balls;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    for (std::size_t j = i + 1; j < balls.size(); ++j)
      overlapRatio = std::max(overlapRatio, (balls[i].radius + balls[j].radius -
                                             (balls[j].position - balls[i].position).norm()) /
                                                std::min(balls[i].radius, balls[j].radius));
    for (const WallDef& w : c.scene.walls) {
      const Vec2 ab = w.b - w.a;
      const double s = std::clamp((balls[i].position - w.a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      overlapRatio =
          std::max(overlapRatio, 1.0 - (w.a + s * ab - balls[i].position).norm() / balls[i].radius);
    }
  }
  bool clamped = false;
  for (std::size_t i = 0; i < balls.size(); ++i)
    clamped =
        clamped ||
        replay.balls[i].velocity.norm() * settings.dt >= kClampFraction * kMaxTranslation ||
        std::abs(replay.balls[i].angularVelocity) * settings.dt >= kClampFraction * kMaxRotation;

  std::vector<Trial> trials;
  Box2DModelSettings t = model;
  t.velocityIterations = kConvergedIterations;
  trials.push_back({Cause::VelocityIterations, "with 100 velocity iterations", t});
  if (overlapRatio >= kBox2DTolerance) {
    t = model;
    t.midOverlapContact = false;
    trials.push_back({Cause::MidOverlapContact, "with the contact point on the surfaces", t});
  }
  if (settings.restitutionThreshold > 0.0) {
    t = model;
    t.restitutionThreshold = 0.0;
    trials.push_back({Cause::RestitutionThreshold, "with restitution threshold 0", t});
  }
  if (clamped) {
    t = model;
    t.motionClamps = false;
    trials.push_back({Cause::OutsideRange, "without Box2D's per-step motion clamps", t});
  }

  // One setting at a time; then all together, where the setting that alone
  // closes most of the gap is named and the others listed.
  Box2DModelSettings all = model;
  all.velocityIterations = kConvergedIterations;
  const Trial* best = nullptr;
  double bestGap = modelGap;
  for (const Trial& trial : trials) {
    const double gap = measureDiscrepancy(c, runBox2DModel(c, trial.settings), ref).relative;
    if (gap <= kBox2DTolerance) {
      a.cause = trial.cause;
      a.detail = describe(trial.what, d, gap);
      return a;
    }
    if (gap < bestGap) {
      bestGap = gap;
      best = &trial;
    }
  }
  all.midOverlapContact = overlapRatio < kBox2DTolerance;
  all.restitutionThreshold = 0.0;
  all.motionClamps = !clamped;
  // With one setting tried, "all together" is that trial again.
  const double allGap =
      trials.size() > 1 ? measureDiscrepancy(c, runBox2DModel(c, all), ref).relative : INFINITY;
  if (allGap <= kBox2DTolerance && best) {
    a.cause = best->cause;
    a.detail = describe(best->what, d, bestGap) +
               "; with every setting moved to the engine's: " + std::to_string(allGap);
    return a;
  }
  if (!c.isolated) {
    a.cause = Cause::SequentialOrder;
    a.detail = describe(
        "Box2D's answer is its own algorithm (replayed in double); it solves the contacts "
        "together, with restitution targets from the pre-solve velocities, the engine one "
        "exchange at a time",
        d, replayGap);
    return a;
  }
  a.cause = Cause::Unexplained;
  a.detail = describe("no single Box2D setting explains the gap to the reference", d, allGap);
  return a;
}

}  // namespace particles::compare
