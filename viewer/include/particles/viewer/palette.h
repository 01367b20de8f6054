// The viewer's colours, one place for the renderer and for the tests that
// look for them in screenshots. Chosen far apart, so that a pixel test can
// tell them apart exactly (rendering is not antialiased off screen).
#pragma once

#include "particles/viewer/debug_draw.h"

namespace particles::viewer::palette {

inline constexpr Color kBackground{24, 26, 32};
inline constexpr Color kWall{200, 200, 200};
inline constexpr Color kEngineBall{66, 135, 245};  // the engine's balls (blue)
inline constexpr Color kBox2DBall{245, 150, 50};   // Box2D's balls, and its ghosts (orange)
inline constexpr Color kMarker{255, 255, 255};     // the angle marker on a filled ball
inline constexpr Color kDrag{60, 220, 90};         // the mouse pull, centre to cursor
inline constexpr Color kNormal{230, 60, 60};       // contact normals (key D)
inline constexpr Color kImpulse{250, 220, 60};     // contact impulses (key D)
inline constexpr Color kDivider{90, 90, 100};      // between the two side-by-side viewports
inline constexpr Color kText{230, 230, 230};
inline constexpr Color kPanel{0, 0, 0, 170};  // behind the readout

}  // namespace particles::viewer::palette
