#include "particles/material.h"

#include <algorithm>
#include <cmath>

namespace particles {

double mixRestitution(double e1, double e2) {
  return std::max(e1, e2);
}

double mixFriction(double mu1, double mu2) {
  if (mu1 == 0.0 || mu2 == 0.0) return 0.0;
  if (std::isinf(mu1) || std::isinf(mu2)) return std::numeric_limits<double>::infinity();
  return std::sqrt(mu1 * mu2);
}

ContactMaterial resolveMaterial(const ContactMaterial& sceneDefault,
                                std::optional<double> restitution, std::optional<double> friction) {
  return {restitution.value_or(sceneDefault.restitution), friction.value_or(sceneDefault.friction)};
}

ContactMaterial mixMaterials(const ContactMaterial& a, const ContactMaterial& b) {
  return {mixRestitution(a.restitution, b.restitution), mixFriction(a.friction, b.friction)};
}

}  // namespace particles
