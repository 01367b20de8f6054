// Where a scene leaves the range in which Box2D 2.4.1 is a trustworthy
// reference. A comparison that disagrees on such a scene says "outside
// Box2D's range", not "engine error". Each limit, and the Box2D constant it
// comes from, is documented in src/box2d_limits.h and docs/box2d-twin.md.
#pragma once

#include <string>
#include <vector>

#include "particles/reference/box2d_settings.h"
#include "particles/scene.h"

namespace particles::reference {

enum class RangeCode {
  FloatRange,          // a value that is not a finite, normal float
  MaxTranslation,      // |v| dt may exceed b2_maxTranslation: Box2D clamps the speed
  MaxRotation,         // |w| dt may exceed b2_maxRotation: Box2D clamps the spin
  RadiusRange,         // radius outside the 0.1-10 m Box2D is tuned for
  LinearSlop,          // radius < 10 b2_linearSlop: the allowed overlap is a visible fraction
  WallLength,          // wall longer than the 50 m static shapes Box2D is tuned for
  PositionPrecision,   // float spacing of coordinates > 1e-3 of the smallest radius
  MassRatio,           // largest / smallest ball mass > 1e6
  NoSlipMixing,        // a no-slip body meets a tiny mu: the mixed Box2D mu may bind
  VelocityIterations,  // < 2: friction of a new contact sees no normal impulse
  PositionIterations,  // < 1: overlaps are never corrected
};

struct RangeIssue {
  RangeCode code;
  int index = -1;       // ball, wall or force concerned; -1 for the whole scene
  std::string message;  // for people: the values involved and the limit
};

// Every issue found, grouped by code in the order of RangeCode; empty for a
// scene well inside Box2D's range.
std::vector<RangeIssue> checkBox2DRange(const SceneDef& scene, const Box2DSettings& settings);

const char* rangeCodeName(RangeCode code);

}  // namespace particles::reference
