// What one source (engine, Box2D, closed form) says a case ends with, and
// the invariant residuals of that answer.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "particles/compare/impact_case.h"
#include "particles/mutation.h"
#include "particles/reference/box2d_settings.h"

namespace particles::compare {

enum class Source { Engine, Box2D, Truth };
std::string_view sourceName(Source s);  // "engine", "box2d", "truth"

struct BodyVelocity {
  Vec2 velocity{0.0, 0.0};       // m/s
  double angularVelocity = 0.0;  // rad/s
};

struct Outcome {
  std::vector<BodyVelocity> balls;  // after the case's one step, in scene order
  bool finite = true;               // no NaN or infinity anywhere
};

// The pre-impact velocities of a case.
Outcome initialState(const ImpactCase& c);
// The same into `out`, reusing its storage.
void initialState(const ImpactCase& c, Outcome& out);

Outcome runEngine(const ImpactCase& c, Mutation mutation = Mutation::None);
Outcome runBox2D(const ImpactCase& c, const reference::Box2DSettings& settings);
// The closed form, for isolated cases only.
std::optional<Outcome> runTruth(const ImpactCase& c);
// The closed form with the lever arms moved to the middle of the overlap
// (r - delta/2), as Box2D places its contact point; isolated cases only.
std::optional<Outcome> runTruthMidOverlap(const ImpactCase& c);

}  // namespace particles::compare
