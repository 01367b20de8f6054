// The impulse formulas as templates on a Mutation, so that the mutants of the
// comparison suite are the real solver with one sign changed, while the
// normal path (Mutation::None) compiles to plain code with no test at all.
// Derivation and sign conventions: docs/physics.md, "Impact".
#pragma once

#include <cmath>

#include "particles/contact_impulse.h"
#include "particles/mutation.h"

namespace particles::detail {

template <Mutation M>
constexpr double flipIf(Mutation m) {
  return M == m ? -1.0 : 1.0;
}

// tau = z x n; the wall mutant turns it the wrong way on wall contacts (a
// wall is the only body with zero inverse mass and inertia).
template <Mutation M>
Vec2 tangentOf(const ContactBody& b, const Vec2& n) {
  if constexpr (M == Mutation::WallTangentFlipped) {
    if (b.invMass == 0.0 && b.invInertia == 0.0) return -perpLeft(n);
  }
  return perpLeft(n);
}

template <Mutation M>
ContactVelocity contactVelocityAs(const ContactBody& a, const ContactBody& b, const Vec2& n) {
  const Vec2 tau = tangentOf<M>(b, n);
  const Vec2 dv = b.velocity - a.velocity;
  // Surface velocities at the contact: a's point is at +r_a n, so it moves
  // with w_a r_a tau; b's point is at -r_b n, so it moves with -w_b r_b tau.
  return {dv.dot(n), flipIf<M>(Mutation::SlipLinearSign) * dv.dot(tau) -
                         flipIf<M>(Mutation::SlipSpinBSign) * b.angularVelocity * b.leverArm -
                         flipIf<M>(Mutation::SlipSpinASign) * a.angularVelocity * a.leverArm};
}

template <Mutation M>
ContactImpulse computeImpulseAs(const ContactBody& a, const ContactBody& b, const Vec2& n,
                                const ContactMaterial& material) {
  ContactImpulse impulse;
  const double invMassSum = a.invMass + b.invMass;
  if (invMassSum <= 0.0) return impulse;  // two immovable bodies exchange nothing
  const ContactVelocity g = contactVelocityAs<M>(a, b, n);
  // A unit lambdaN changes gn by (1/m_a + 1/m_b); we want gn' = -e gn for
  // the approach the bodies brought into the step. The part of gn that this
  // step's forces added (gravity pressing a ball on the floor) is cancelled
  // but not bounced: bouncing it would return g dt more speed than came in
  // at every bounce, and a resting elastic ball would hop ever higher.
  const double e = flipIf<M>(Mutation::RestitutionSign) * material.restitution;
  const double forced = (b.forcedVelocity - a.forcedVelocity).dot(n);
  const double brought = g.normal - forced;
  const double change = brought < 0.0 ? -(1.0 + e) * brought - forced : -g.normal;
  impulse.normal = flipIf<M>(Mutation::NormalImpulseSign) * change / invMassSum;
  if (material.friction == 0.0) return impulse;  // smooth: no tangential work at all

  // A unit lambdaT changes gt by 1/m_a + 1/m_b + r_a^2/J_a + r_b^2/J_b; the
  // no-slip impulse makes gt' = 0.
  const double tangentCompliance =
      invMassSum + a.leverArm * a.leverArm * a.invInertia + b.leverArm * b.leverArm * b.invInertia;
  impulse.unclamped = -flipIf<M>(Mutation::TangentImpulseSign) * g.tangent / tangentCompliance;
  impulse.tangent = impulse.unclamped;
  const double bound = material.friction * std::abs(impulse.normal);  // inf * x = inf: no-slip
  if (std::abs(impulse.unclamped) > bound) {
    // Coulomb: the magnitude is clamped, the direction (sign) is kept.
    impulse.tangent =
        M == Mutation::ClampDropsSign ? bound : std::copysign(bound, impulse.unclamped);
    impulse.clamped = true;
  }
  return impulse;
}

template <Mutation M>
void applyImpulseAs(ContactBody& a, ContactBody& b, const Vec2& n, const ContactImpulse& impulse) {
  const Vec2 p = impulse.normal * n + impulse.tangent * tangentOf<M>(b, n);
  a.velocity -= flipIf<M>(Mutation::ImpulseOnASign) * a.invMass * p;
  b.velocity += b.invMass * p;
  // Torque impulse about each centre: (contact - centre) x (impulse on body).
  // a: (r_a n) x (-P) = -r_a lambdaT;  b: (-r_b n) x (+P) = -r_b lambdaT.
  a.angularVelocity -=
      flipIf<M>(Mutation::SpinUpdateASign) * a.leverArm * impulse.tangent * a.invInertia;
  b.angularVelocity -=
      flipIf<M>(Mutation::SpinUpdateBSign) * b.leverArm * impulse.tangent * b.invInertia;
}

template <Mutation M>
ContactImpulse resolveImpactAs(ContactBody& a, ContactBody& b, const Vec2& n,
                               const ContactMaterial& material) {
  const ContactImpulse impulse = computeImpulseAs<M>(a, b, n, material);
  applyImpulseAs<M>(a, b, n, impulse);
  return impulse;
}

// Calls f.template operator()<M>() with the Mutation m as a compile-time
// constant: one switch at the top of a stage, none in its loops.
template <typename F>
decltype(auto) withMutation(Mutation m, F&& f) {
  switch (m) {
    case Mutation::None:
      return f.template operator()<Mutation::None>();
    case Mutation::NormalImpulseSign:
      return f.template operator()<Mutation::NormalImpulseSign>();
    case Mutation::RestitutionSign:
      return f.template operator()<Mutation::RestitutionSign>();
    case Mutation::TangentImpulseSign:
      return f.template operator()<Mutation::TangentImpulseSign>();
    case Mutation::SlipLinearSign:
      return f.template operator()<Mutation::SlipLinearSign>();
    case Mutation::SlipSpinASign:
      return f.template operator()<Mutation::SlipSpinASign>();
    case Mutation::SlipSpinBSign:
      return f.template operator()<Mutation::SlipSpinBSign>();
    case Mutation::ImpulseOnASign:
      return f.template operator()<Mutation::ImpulseOnASign>();
    case Mutation::SpinUpdateASign:
      return f.template operator()<Mutation::SpinUpdateASign>();
    case Mutation::SpinUpdateBSign:
      return f.template operator()<Mutation::SpinUpdateBSign>();
    case Mutation::ClampDropsSign:
      return f.template operator()<Mutation::ClampDropsSign>();
    case Mutation::WallTangentFlipped:
      return f.template operator()<Mutation::WallTangentFlipped>();
  }
  return f.template operator()<Mutation::None>();
}

}  // namespace particles::detail
