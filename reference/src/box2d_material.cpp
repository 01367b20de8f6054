#include "box2d_material.h"

#include <cmath>

namespace particles::reference {

FixtureMaterial toBox2DMaterial(const ContactMaterial& material, const Box2DSettings& settings) {
  FixtureMaterial out;
  const double mu = std::isinf(material.friction) ? settings.noSlipFriction : material.friction;
  out.friction = static_cast<float>(mu);
  out.restitution = static_cast<float>(material.restitution);
  out.restitutionThreshold = static_cast<float>(settings.restitutionThreshold);
  return out;
}

}  // namespace particles::reference
