// Box2D 2.4.1's limits as the range check uses them, each with the Box2D
// constant or manual section it comes from (docs/box2d-twin.md, "Limits").
#pragma once

#include <box2d/b2_common.h>

namespace particles::reference::limits {

// b2_maxTranslation (2 m): b2Island::Solve scales a velocity down so that no
// body moves further than this in one step.
inline constexpr double kMaxTranslation = b2_maxTranslation;
// b2_maxRotation (pi/2 rad): likewise for the angle turned in one step.
inline constexpr double kMaxRotation = b2_maxRotation;
// b2_linearSlop (0.005 m): the overlap Box2D leaves in resting contacts and
// ignores in its position solver. Below 10 slops per radius, that tolerated
// overlap is over a tenth of the ball.
inline constexpr double kLinearSlop = b2_linearSlop;
inline constexpr double kMinSlopsPerRadius = 10.0;
// Box2D 2.4 manual, "Units": tolerances are tuned for moving shapes of
// 0.1-10 m and static shapes up to 50 m (b2_linearSlop, b2_aabbExtension,
// b2_maxLinearCorrection are all fixed lengths in metres).
inline constexpr double kMinRadius = 0.1;
inline constexpr double kMaxRadius = 10.0;
inline constexpr double kMaxWallLength = 50.0;
// Box2D stores positions as float (24-bit significand): the spacing of floats
// at the largest coordinate must stay below this fraction of the smallest
// radius, or contact geometry is quantised visibly.
inline constexpr double kPositionResolution = 1e-3;
// Float mass ratios: the heavy ball's velocity change in a collision is
// ~(m_light / m_heavy) of its speed; beyond 1e6 that is a few float ulps
// (FLT_EPSILON = 1.2e-7) and momentum exchange becomes rounding noise.
inline constexpr double kMaxMassRatio = 1e6;
// A no-slip contact mixed in Box2D to mu below this may clamp its friction
// impulse (it binds when the approach speed is below slip speed / mu).
inline constexpr double kEffectivelyNoSlip = 1e3;

}  // namespace particles::reference::limits
