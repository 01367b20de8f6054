// Derivation and sign conventions: docs/physics.md, "Impact".
#include "particles/contact_impulse.h"

#include <algorithm>
#include <cmath>

namespace particles {

ContactVelocity contactVelocity(const ContactBody& a, const ContactBody& b, const Vec2& n) {
  const Vec2 tau = perpLeft(n);
  const Vec2 dv = b.velocity - a.velocity;
  // Surface velocities at the contact: a's point is at +r_a n, so it moves
  // with w_a r_a tau; b's point is at -r_b n, so it moves with -w_b r_b tau.
  return {dv.dot(n), dv.dot(tau) - b.angularVelocity * b.leverArm - a.angularVelocity * a.leverArm};
}

ContactImpulse computeImpulse(const ContactBody& a, const ContactBody& b, const Vec2& n,
                              const ContactMaterial& material) {
  ContactImpulse impulse;
  const double invMassSum = a.invMass + b.invMass;
  if (invMassSum <= 0.0) return impulse;  // two immovable bodies exchange nothing
  const ContactVelocity g = contactVelocity(a, b, n);
  // A unit lambdaN changes gn by (1/m_a + 1/m_b); we want gn' = -e gn.
  impulse.normal = -(1.0 + material.restitution) * g.normal / invMassSum;
  if (material.friction == 0.0) return impulse;  // smooth: no tangential work at all

  // A unit lambdaT changes gt by 1/m_a + 1/m_b + r_a^2/J_a + r_b^2/J_b; the
  // no-slip impulse makes gt' = 0.
  const double tangentCompliance = invMassSum + a.leverArm * a.leverArm * a.invInertia +
                                   b.leverArm * b.leverArm * b.invInertia;
  impulse.unclamped = -g.tangent / tangentCompliance;
  impulse.tangent = impulse.unclamped;
  const double bound = material.friction * std::abs(impulse.normal);  // inf * x = inf: no-slip
  if (std::abs(impulse.unclamped) > bound) {
    impulse.tangent = std::copysign(bound, impulse.unclamped);  // Coulomb: sign kept
    impulse.clamped = true;
  }
  return impulse;
}

void applyImpulse(ContactBody& a, ContactBody& b, const Vec2& n, const ContactImpulse& impulse) {
  const Vec2 p = impulse.normal * n + impulse.tangent * perpLeft(n);
  a.velocity -= a.invMass * p;
  b.velocity += b.invMass * p;
  // Torque impulse about each centre: (contact - centre) x (impulse on body).
  // a: (r_a n) x (-P) = -r_a lambdaT;  b: (-r_b n) x (+P) = -r_b lambdaT.
  a.angularVelocity -= a.leverArm * impulse.tangent * a.invInertia;
  b.angularVelocity -= b.leverArm * impulse.tangent * b.invInertia;
}

ContactImpulse resolveImpact(ContactBody& a, ContactBody& b, const Vec2& n,
                             const ContactMaterial& material) {
  const ContactImpulse impulse = computeImpulse(a, b, n, material);
  applyImpulse(a, b, n, impulse);
  return impulse;
}

}  // namespace particles
