// Box2D 2.4.1's contact velocity solver replayed in double, so that the
// comparator can attribute a Box2D answer by reproducing it: "Box2D's answer
// is its own algorithm in double with X". What is replicated, and how the
// contact order is found, is in docs/box2d-twin.md ("Box2D's algorithm,
// replayed in double"). Includes no Box2D and calls no engine solver code.
#pragma once

#include <vector>

#include "particles/compare/outcome.h"

namespace particles::compare {

struct Box2DModelSettings {
  // Sequential-impulse sweeps over the contacts (dimensionless count), as
  // Box2DSettings::velocityIterations.
  int velocityIterations = 8;
  // m/s, >= 0: an approach slower than this gets no restitution bias, as
  // Box2DSettings::restitutionThreshold.
  double restitutionThreshold = 0.0;
  // Dimensionless mu that stands for kNoSlip, as Box2DSettings::noSlipFriction.
  double noSlipFriction = 1e12;
  // true: Box2D's contact point, the middle of the overlap (lever arms
  // r - overlap/2). false, for what-if checks: each ball's lever arm reaches
  // its own surface along the normal, r_a n and -r_b n (the engine's and the
  // closed form's lever arms; for a ball against a wall, the point on the
  // ball's surface).
  bool midOverlapContact = true;
  // b2Island::Solve's per-step clamps: a velocity that would move a body more
  // than b2_maxTranslation (2 m) or turn it more than b2_maxRotation (pi/2) in
  // one step is scaled down to that bound. false leaves them out.
  bool motionClamps = true;
};

// One touching contact of the model's single step.
struct Box2DModelContact {
  bool wall = false;  // false: balls a and b, a < b; true: ball a and wall b
  int a = 0;
  int b = 0;
  // Position in b2World's contact list among the touching contacts (the order
  // Box2DWorld::contacts() reports them in), 0 = first.
  int worldListIndex = 0;
  // Accumulated impulses after the last iteration, in N s, in Box2D's frame:
  // the normal points from fixture A to fixture B (the wall, or the lower
  // ball, is A) and the tangent is (n_y, -n_x), as ContactInfo reports them.
  double normalImpulse = 0.0;
  double tangentImpulse = 0.0;
};

struct Box2DModelResult {
  Outcome outcome;
  // Touching contacts in the order the island solver visits them.
  std::vector<Box2DModelContact> contacts;
};

// Velocities after one Box2D step of the case, computed in double with
// Box2D's algorithm.
Outcome runBox2DModel(const ImpactCase& c, const Box2DModelSettings& settings);

// The same step, with the contacts and their impulses.
Box2DModelResult runBox2DModelDetailed(const ImpactCase& c, const Box2DModelSettings& settings);

}  // namespace particles::compare
