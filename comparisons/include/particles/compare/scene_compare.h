// `particles compare`: a scene run in the engine and in its Box2D twin side
// by side; every collision event of one is matched with the other's by the
// pair of bodies and the time, and their pre- and post-collision velocities
// are compared.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "particles/compare/outcome.h"
#include "particles/reference/box2d_settings.h"
#include "particles/scene.h"
#include "particles/world.h"

namespace particles::compare {

// One body's velocities before and after the step of a collision.
struct EventBody {
  int ball = 0;
  BodyVelocity before, after;
};

// A contact that exchanged a normal impulse during one step.
struct CollisionEvent {
  int a = 0;  // ball index
  int b = 0;  // ball index, or wall index when `wall`
  bool wall = false;
  long long step = 0;             // the step (0-based) during which it happened
  double time = 0.0;              // s, at the start of that step
  std::vector<EventBody> bodies;  // a, then b unless it is a wall
};

struct MatchedEvent {
  CollisionEvent engine, box2d;
  double velocityDifference = 0.0;  // m/s, largest |dv| after, over the bodies
  double spinDifference = 0.0;      // rad/s, largest |dw| after
  double relative = 0.0;  // the larger of both, over the bodies' largest speed before or after
};

struct SceneComparison {
  std::string scene;  // file or scene name
  long long steps = 0;
  std::vector<MatchedEvent> matched;
  std::vector<CollisionEvent> engineOnly, box2dOnly;
  std::vector<std::string> rangeIssues;  // where the scene leaves Box2D's range
  double worstRelative = 0.0;
  // Final states, and their largest differences.
  std::vector<BallState> engineFinal, box2dFinal;
};

struct CompareSettings {
  reference::Box2DSettings box2d;  // dt is taken from the scene
  // Events whose steps differ by at most this many are the same collision.
  int matchWindowSteps = 2;
};

SceneComparison compareScene(const SceneDef& scene, const std::string& label,
                             const CompareSettings& settings);

nlohmann::json comparisonJson(const SceneComparison& c);
// A short human summary: counts, worst differences, the unmatched events.
std::string comparisonText(const SceneComparison& c);

}  // namespace particles::compare
