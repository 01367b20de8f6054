// What a world looks like, drawn through DebugDraw: walls, balls with their
// angle markers, the mouse pull and the contacts. Pure functions of the
// states, so tests can check what is drawn with a recording DebugDraw.
#pragma once

#include <vector>

#include "particles/reference/box2d_inspect.h"
#include "particles/scene.h"
#include "particles/viewer/debug_draw.h"
#include "particles/world.h"

namespace particles::viewer {

// How the balls of one world are drawn.
struct BallLook {
  // true: a filled disk with a radius marker at the ball's angle;
  // false: a ghost, the outline and the radius marker only (overlay mode).
  bool filled = true;
  Color color;   // fill, or the ghost's outline and marker
  Color marker;  // the marker on a filled ball
};

// Seconds by which an impulse arrow scales the velocity change it gives its
// ball: an arrow is |P| / m * kImpulseArrowSeconds long (m), capped at
// kImpulseArrowRadii radii of that ball so that a hard hit stays on screen.
inline constexpr double kImpulseArrowSeconds = 0.1;
inline constexpr double kImpulseArrowRadii = 2.0;
// Contact normals are drawn kNormalRadii radii of ball a long.
inline constexpr double kNormalRadii = 0.6;

void drawWalls(DebugDraw& draw, const SceneDef& scene);

// balls[i] is the state of scene.balls[i]; non-finite states are skipped.
void drawBalls(DebugDraw& draw, const SceneDef& scene, const std::vector<BallState>& balls,
               const BallLook& look);

// The handout's pull F = k (M - O): a segment from the centre O to the
// cursor M, and a dot at M.
void drawPull(DebugDraw& draw, const Vec2& centre, const Vec2& cursor);

// The engine's impacts (World::impacts()): each contact's normal at the
// contact point c = x_a + r_a n, and the impulse each ball received there
// (-P for a, +P for b; P = lambda_n n + lambda_t tau) as arrows.
void drawImpacts(DebugDraw& draw, const SceneDef& scene, const std::vector<BallState>& balls,
                 const std::vector<ImpactEvent>& impacts);

// Box2D's touching contacts: the normal from the geometry (Box2D's own
// manifold normal is not exposed) and the normal impulse of the last step
// as arrows; Box2D's tangent frame is not exposed either, so no friction.
void drawBox2DContacts(DebugDraw& draw, const SceneDef& scene, const std::vector<BallState>& balls,
                       const std::vector<reference::ContactInfo>& contacts);

}  // namespace particles::viewer
