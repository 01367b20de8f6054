// Contact material: restitution and Coulomb friction, and how two bodies'
// values combine into the value used at their contact.
#pragma once

#include <optional>

namespace particles {

struct ContactMaterial {
  // Bounce factor e in [0, 1]: the normal relative velocity after an impact is
  // -e times the one before. Dimensionless.
  double restitution = 1.0;
  // Coulomb coefficient mu >= 0. 0 is smooth (no tangential impulse),
  // kNoSlip (infinity) is the handout's no-slip impact. Dimensionless.
  double friction = 0.0;
};

// Box2D's mixing rules, so that a scene means the same in both engines:
// restitution = max(e1, e2), friction = sqrt(mu1 * mu2). Infinity (no-slip)
// mixed with any mu > 0 stays infinite; anything mixed with 0 is 0, because a
// smooth surface cannot grip (and sqrt(inf * 0) would be NaN).
double mixRestitution(double e1, double e2);
double mixFriction(double mu1, double mu2);

// A body's own values: an override if it has one, else the scene default.
ContactMaterial resolveMaterial(const ContactMaterial& sceneDefault,
                                std::optional<double> restitution, std::optional<double> friction);

ContactMaterial mixMaterials(const ContactMaterial& a, const ContactMaterial& b);

}  // namespace particles
