// The live readout: energies and momentum of each world, and how far apart
// the engine and its Box2D twin are. Numbers first (tested), text second.
#pragma once

#include <string>
#include <vector>

#include "particles/scene.h"
#include "particles/viewer/session.h"
#include "particles/viewer/view_mode.h"
#include "particles/world.h"

namespace particles::viewer {

struct EnergyReadout {
  double translational = 0.0;  // J, sum of m |v|^2 / 2
  double rotational = 0.0;     // J, sum of I w^2 / 2
  // J, sum of -m g . x: the scene's gravity g, zero on the line through the
  // origin across g (y = 0 for vertical gravity).
  double potential = 0.0;
  Vec2 momentum{0.0, 0.0};  // kg m/s, sum of m v
  double total() const { return translational + rotational + potential; }
};

// balls[i] is the state of scene.balls[i] (mass and inertia from the scene).
EnergyReadout measureEnergy(const SceneDef& scene, const std::vector<BallState>& balls);

// The largest difference between the two worlds over the balls, now.
struct Discrepancy {
  double position = 0.0;  // m, max |x_engine - x_box2d|
  int positionBall = -1;  // which ball; -1 with no balls
  double velocity = 0.0;  // m/s, max |v_engine - v_box2d|
  int velocityBall = -1;
};
Discrepancy largestDifference(const std::vector<BallState>& engine,
                              const std::vector<BallState>& box2d);

// The readout's lines, top to bottom: time and state, one line per world,
// the discrepancy, and the pull while a ball is held.
std::vector<std::string> readoutLines(const Session& session, ViewMode mode);

// The key reminder shown at the bottom of the window; the mouse part is left
// out when the window is too narrow for it.
std::string keyHelpLine(bool withMouse);

}  // namespace particles::viewer
