#include "particles/contact_impulse.h"

#include "contact_impulse_impl.h"

namespace particles {

using detail::withMutation;

ContactVelocity contactVelocity(const ContactBody& a, const ContactBody& b, const Vec2& n) {
  return detail::contactVelocityAs<Mutation::None>(a, b, n);
}

ContactImpulse computeImpulse(const ContactBody& a, const ContactBody& b, const Vec2& n,
                              const ContactMaterial& material, Mutation mutation) {
  return withMutation(mutation,
                      [&]<Mutation M>() { return detail::computeImpulseAs<M>(a, b, n, material); });
}

void applyImpulse(ContactBody& a, ContactBody& b, const Vec2& n, const ContactImpulse& impulse,
                  Mutation mutation) {
  withMutation(mutation, [&]<Mutation M>() { detail::applyImpulseAs<M>(a, b, n, impulse); });
}

ContactImpulse resolveImpact(ContactBody& a, ContactBody& b, const Vec2& n,
                             const ContactMaterial& material, Mutation mutation) {
  return withMutation(mutation,
                      [&]<Mutation M>() { return detail::resolveImpactAs<M>(a, b, n, material); });
}

}  // namespace particles
