// The handout's exchanged impulse, for one contact between two bodies.
//
// Conventions (derived in docs/physics.md): n is the unit normal from body a
// to body b, tau = z x n = (-n_y, n_x). Body b receives +P and body a -P, with
// P = lambdaN n + lambdaT tau. A wall is body b with zero inverse mass and
// inverse inertia: the same formulas, not a special case.
#pragma once

#include "particles/material.h"
#include "particles/mutation.h"
#include "particles/types.h"

namespace particles {

// The velocity state and mass properties of one side of a contact.
struct ContactBody {
  Vec2 velocity{0.0, 0.0};       // m/s
  double angularVelocity = 0.0;  // rad/s
  double invMass = 0.0;          // 1/kg; 0 for a wall
  double invInertia = 0.0;       // 1/(kg m^2); 0 for a wall
  double leverArm = 0.0;         // m, distance from the centre to the contact point
  // m/s, the part of `velocity` that this step's external forces (gravity,
  // pulls, constant forces) added. Restitution bounces only the approach the
  // bodies brought into the step; what the forces added is cancelled, not
  // bounced (docs/physics.md, "Restitution and the step's forces").
  Vec2 forcedVelocity{0.0, 0.0};
};

// Relative velocity of b's surface with respect to a's surface at the contact,
// split into normal and tangential parts. gn < 0 means approaching.
struct ContactVelocity {
  double normal = 0.0;   // m/s, (v_b - v_a) . n
  double tangent = 0.0;  // m/s, (v_b - v_a) . tau - w_b r_b - w_a r_a
};

struct ContactImpulse {
  double normal = 0.0;     // N s, lambdaN >= 0 for an approaching contact
  double tangent = 0.0;    // N s, lambdaT
  double unclamped = 0.0;  // N s, the no-slip lambdaT before the Coulomb clamp
  bool clamped = false;    // true when |unclamped| > mu * lambdaN (sliding)
};

ContactVelocity contactVelocity(const ContactBody& a, const ContactBody& b, const Vec2& n);

// Impulse for an approaching contact: lambdaN gives a normal relative velocity
// of -e gn afterwards; lambdaT cancels the tangential slip (no-slip), clamped
// to |lambdaT| <= mu lambdaN with its sign kept. With mu == 0 no tangential
// impulse is computed at all.
// `mutation` is for the comparison suite's mutation check only.
ContactImpulse computeImpulse(const ContactBody& a, const ContactBody& b, const Vec2& n,
                              const ContactMaterial& material, Mutation mutation = Mutation::None);

// Applies -P to a and +P to b, with the angular updates w -= r lambdaT / J.
void applyImpulse(ContactBody& a, ContactBody& b, const Vec2& n, const ContactImpulse& impulse,
                  Mutation mutation = Mutation::None);

// computeImpulse + applyImpulse.
ContactImpulse resolveImpact(ContactBody& a, ContactBody& b, const Vec2& n,
                             const ContactMaterial& material, Mutation mutation = Mutation::None);

}  // namespace particles
