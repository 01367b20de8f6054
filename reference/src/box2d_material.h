// A body's contact material as Box2D fixture values. Each fixture carries its
// own body's material (the override or the scene default); Box2D 2.4.1 mixes
// two fixtures exactly as the engine does (b2MixFriction = sqrt(f1 f2),
// b2MixRestitution = max(r1, r2), b2_contact.h), so the contact ends up with
// the engine's mixMaterials value.
#pragma once

#include "particles/material.h"
#include "particles/reference/box2d_settings.h"

namespace particles::reference {

struct FixtureMaterial {
  float friction = 0.0f;
  float restitution = 0.0f;
  // m/s. Box2D applies restitution only to approaches faster than this
  // (b2Fixture::restitutionThreshold, 1 m/s by default, mixed as the minimum).
  // The engine applies it to every approach, so the twin uses 0 unless
  // Box2DSettings::restitutionThreshold says otherwise.
  float restitutionThreshold = 0.0f;
};

// kNoSlip (infinity) becomes settings.noSlipFriction.
FixtureMaterial toBox2DMaterial(const ContactMaterial& material, const Box2DSettings& settings);

}  // namespace particles::reference
