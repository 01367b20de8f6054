// The stability envelope (docs/stress.md): stress cases along the issue's
// axes, what is observed of a run, and the classification stable / broken.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "particles/scene.h"
#include "particles/timestep/stepper.h"

namespace particles::timestep {

// What a stress run showed; filled by observeStress() or, in tests, by hand.
struct StressObservation {
  bool finite = true;          // no NaN or infinity in any state, ever
  double energyStart = 0.0;    // J: kinetic + rotational + potential (-m g.x)
  double energyMax = 0.0;      // J: the largest total seen
  double energyScale = 0.0;    // J, > 0: what "1 %" of the energy is measured against
  bool tunnelled = false;      // a ball passed through a wall or another ball
  bool atRest = false;         // the case ends at rest: its overlap counts
  double overlapAtRest = 0.0;  // largest overlap at the end / that ball's radius (dimensionless)
  double kineticAtEnd = 0.0;   // J, kinetic + rotational at the end
};

// The criteria (issue 4): stable means no NaN or infinity, energy that
// grows by at most kEnergyGrowth of energyScale, no tunnelling, and, for a
// case that ends at rest, overlap below kRestOverlap of the radius.
inline constexpr double kEnergyGrowth = 0.01;
inline constexpr double kRestOverlap = 0.01;

struct Verdict {
  bool stable = true;
  std::string
      reasons;  // "non-finite", "energy +12 %", "tunnelled", "overlap 3.1 % r"; joined by "; "
};
Verdict classify(const StressObservation& o);

struct StressCase {
  std::string axis;   // "mass ratio", "radius ratio", "speed", "grazing", "elastic gas", "dense
                      // pile", "scale"
  std::string value;  // the point on the axis, as text ("1e-06", "2 r/step", ...)
  SceneDef scene;     // dt and duration: the run
  bool endsAtRest = false;
  // True when the final state shows a ball through a wall or another ball.
  std::function<bool(std::span<const BallState>)> tunnelled;
};

// Every case; `longGas`: the elastic gas for 1e6 steps instead of 1e4.
std::vector<StressCase> stressCases(bool longGas);

// Runs `steps` steps, checking finiteness and energy every `every` steps
// and at the end.
StressObservation observeStress(Stepper& s, const StressCase& c, long long every = 1);

// Energy of a state under the scene's gravity (J), and the largest overlap
// (ball-ball and ball-wall) divided by the smaller radius involved.
double sceneEnergy(const SceneDef& scene, std::span<const BallState> balls);
double maxRelativeOverlap(const SceneDef& scene, std::span<const BallState> balls);

}  // namespace particles::timestep
