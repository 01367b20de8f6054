// How the Box2D twin steps its world. Kept free of Box2D types so that callers
// never include Box2D (docs/box2d-twin.md).
#pragma once

#include "particles/scene.h"

namespace particles::reference {

struct Box2DSettings {
  // s, > 0: the time step passed to b2World::Step (as a float). Usually the
  // scene's dt; forScene() copies it. The twin's clock is step index * dt.
  double dt = 0.0;
  // Velocity-solver iterations per step (dimensionless count). Box2D solves a
  // contact's friction before its normal impulse within one iteration, so at
  // least 2 are needed for friction to see the normal impulse of a new
  // contact (checkBox2DRange flags fewer). 8 is Box2D's recommended value.
  int velocityIterations = 8;
  // Position-solver iterations per step (dimensionless count); 0 leaves
  // overlaps uncorrected. 3 is Box2D's recommended value.
  int positionIterations = 3;
  // Dimensionless Coulomb coefficient that stands for the engine's kNoSlip
  // (infinity). Box2D clamps the accumulated friction impulse to
  // mu * (normal impulse), and infinity would make that clamp NaN when the
  // normal impulse is 0 (inf * 0). 1e12 never binds in practice: mixed with a
  // partner's mu it becomes sqrt(1e12 mu), still >= 1e3 for any mu >= 1e-6,
  // while 1e12 * 1e12 (two no-slip fixtures mixed) and 1e12 times any
  // plausible impulse stay far below FLT_MAX (3.4e38).
  double noSlipFriction = 1e12;
  // Box2D's continuous collision (time of impact sub-steps against walls).
  // Off by default because the engine is purely discrete: with it on, a ball
  // that would cross into a wall during a step is moved back to the moment of
  // impact and bounces within the same step, so its timing differs from the
  // engine's by up to a step. Turn on to see stock Box2D behaviour.
  bool continuousPhysics = false;
  // m/s, >= 0. Box2D bounces only approaches faster than this
  // (b2FixtureDef::restitutionThreshold, 1 m/s in stock Box2D). The engine
  // bounces every approach, so the twin uses 0; the comparator's attribution
  // tests set it to show what the stock value does.
  double restitutionThreshold = 0.0;

  bool operator==(const Box2DSettings&) const = default;

  // Settings with dt = scene.dt and everything else at its default.
  static Box2DSettings forScene(const SceneDef& scene);
};

}  // namespace particles::reference
