#include "particles/compare/invariants.h"

#include <cmath>
#include <limits>

#include "case_geometry.h"

namespace particles::compare {
namespace {

constexpr double kNotApplicable = std::numeric_limits<double>::quiet_NaN();
// Keeps scales away from zero for a case at rest; far below any real value.
constexpr double kTiny = 1e-300;

double energy(const SceneDef& s, const Outcome& o) {
  double e = 0.0;
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    const BallDef& b = s.balls[i];
    e += 0.5 * b.mass * o.balls[i].velocity.squaredNorm() +
         0.5 * b.resolvedInertia() * o.balls[i].angularVelocity * o.balls[i].angularVelocity;
  }
  return e;
}

// Angular momentum of ball i about point p: J w + m (x - p) x v.
double angularMomentum(const BallDef& b, const BodyVelocity& v, const Vec2& p) {
  return b.resolvedInertia() * v.angularVelocity + b.mass * cross(b.position - p, v.velocity);
}

double angularScale(const BallDef& b, const BodyVelocity& v, const Vec2& p) {
  return b.resolvedInertia() * std::abs(v.angularVelocity) +
         b.mass * (b.position - p).norm() * v.velocity.norm();
}

void measureIsolated(const ImpactCase& c, const Outcome& before, const Outcome& after,
                     double speedScale, Invariants& inv) {
  const SceneDef& s = c.scene;
  const detail::ContactFrame f = detail::contactFrame(c);
  const ContactMaterial m = detail::contactMaterial(c);
  const Vec2 n = f.normal, tau = perpLeft(n);
  const bool wall = f.wall;
  const BallDef& a = s.balls[0];

  // Each ball's angular momentum about its contact point is unchanged: the
  // exchanged impulse acts at that point, its surface point x + r n (a) or
  // x - r n (b). At exact contact both are the same point; cases start with
  // a tiny overlap (kPlacementOverlap), and then each ball has its own.
  inv.angularMomentum = 0.0;
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    const Vec2 point = i == 0 ? f.point : Vec2(s.balls[1].position - s.balls[1].radius * n);
    const double dl = angularMomentum(s.balls[i], after.balls[i], point) -
                      angularMomentum(s.balls[i], before.balls[i], point);
    const double scale = angularScale(s.balls[i], before.balls[i], point) +
                         angularScale(s.balls[i], after.balls[i], point) + kTiny;
    inv.angularMomentum = std::max(inv.angularMomentum, std::abs(dl) / scale);
  }

  // The impulse b received, read off the velocity change.
  const Vec2 p = wall
                     ? Vec2(-a.mass * (after.balls[0].velocity - before.balls[0].velocity))
                     : Vec2(s.balls[1].mass * (after.balls[1].velocity - before.balls[1].velocity));
  inv.normalImpulse = p.dot(n);
  inv.tangentImpulse = p.dot(tau);

  auto slip = [&](const Outcome& o) {
    const Vec2 vb = wall ? Vec2::Zero() : o.balls[1].velocity;
    const double wb = wall ? 0.0 : o.balls[1].angularVelocity * s.balls[1].radius;
    const Vec2 dv = vb - o.balls[0].velocity;
    return std::pair{dv.dot(n), dv.dot(tau) - wb - o.balls[0].angularVelocity * a.radius};
  };
  const auto [gn, gt] = slip(before);
  const auto [gn2, gt2] = slip(after);

  inv.restitution = gn < 0.0 ? std::abs(gn2 + m.restitution * gn) / std::abs(gn) : kNotApplicable;
  inv.noSlip = std::isinf(m.friction) ? std::abs(gt2) / speedScale : kNotApplicable;
  const double impulseScale = std::abs(inv.normalImpulse) + std::abs(inv.tangentImpulse) + kTiny;
  inv.coulomb = std::isinf(m.friction)
                    ? kNotApplicable
                    : std::max(0.0, std::abs(inv.tangentImpulse) - m.friction * inv.normalImpulse) /
                          impulseScale;
  // Friction opposes the slip: lambdaT and gt have opposite signs (or
  // lambdaT is negligible).
  inv.tangentSign = m.friction > 0.0 && inv.tangentImpulse * gt > 0.0 &&
                            std::abs(inv.tangentImpulse) > 1e-9 * impulseScale
                        ? 1.0
                        : 0.0;
}

}  // namespace

Invariants measureInvariants(const ImpactCase& c, const Outcome& after) {
  const SceneDef& s = c.scene;
  // Reused per thread: this runs for every source of every case, and the
  // allocation would cost more than the arithmetic.
  thread_local Outcome before;
  initialState(c, before);
  Invariants inv;
  inv.momentum = inv.angularMomentum = inv.restitution = inv.noSlip = inv.coulomb = kNotApplicable;

  double speedScale = kTiny, momentumScale = kTiny;
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    const BallDef& b = s.balls[i];
    speedScale = std::max(speedScale, before.balls[i].velocity.norm() +
                                          std::abs(before.balls[i].angularVelocity) * b.radius);
    momentumScale += b.mass * (before.balls[i].velocity.norm() + after.balls[i].velocity.norm());
  }

  const double e0 = energy(s, before);
  inv.energyChange = (energy(s, after) - e0) / (e0 + kTiny);

  if (s.walls.empty()) {
    Vec2 dp = Vec2::Zero();
    double dl = 0.0, lScale = kTiny;
    for (std::size_t i = 0; i < s.balls.size(); ++i) {
      dp += s.balls[i].mass * (after.balls[i].velocity - before.balls[i].velocity);
      dl += angularMomentum(s.balls[i], after.balls[i], Vec2::Zero()) -
            angularMomentum(s.balls[i], before.balls[i], Vec2::Zero());
      lScale += angularScale(s.balls[i], before.balls[i], Vec2::Zero()) +
                angularScale(s.balls[i], after.balls[i], Vec2::Zero());
    }
    inv.momentum = dp.norm() / momentumScale;
    inv.angularMomentum = std::abs(dl) / lScale;
    if (!c.isolated) {
      // d |lambdaT| per touching pair, with |lambdaT| <= the momentum scale.
      double slack = 0.0;
      for (std::size_t i = 0; i < s.balls.size(); ++i)
        for (std::size_t j = i + 1; j < s.balls.size(); ++j) {
          const double overlap = s.balls[i].radius + s.balls[j].radius -
                                 (s.balls[j].position - s.balls[i].position).norm();
          if (overlap > 0.0) slack += overlap * momentumScale;
        }
      inv.angularMomentumSlack = slack / lScale;
    }
  }
  if (c.isolated) measureIsolated(c, before, after, speedScale, inv);
  return inv;
}

InvariantTolerance toleranceFor(Source s) {
  // Double sources: residuals are rounding of a few operations on values of
  // the case's scale, amplified at most by the mass and inertia ratios
  // (<= 1e3 in generated cases): 1e3 * 1e-16 * margin. Box2D works in float
  // (6e-8): the same ratios give up to 6e-5; a margin of ~10 gives 1e-3.
  if (s == Source::Box2D) return {1e-3, 1e-3};
  return {1e-9, 1e-9};
}

std::vector<std::string> violatedInvariants(const Invariants& inv, const InvariantTolerance& tol) {
  std::vector<std::string> out;
  auto check = [&](double v, const char* name) {
    if (!std::isnan(v) && v > tol.conservation) out.push_back(name);
  };
  check(inv.momentum, "momentum");
  if (!std::isnan(inv.angularMomentum) &&
      inv.angularMomentum > tol.conservation + inv.angularMomentumSlack)
    out.push_back("angular momentum");
  check(inv.restitution, "restitution");
  check(inv.noSlip, "no-slip");
  check(inv.coulomb, "Coulomb bound");
  if (inv.energyChange > tol.energyGrowth) out.push_back("energy growth");
  if (inv.tangentSign != 0.0) out.push_back("tangent impulse sign");
  return out;
}

}  // namespace particles::compare
