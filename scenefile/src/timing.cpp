#include <cmath>

#include "particles/scenefile.h"

namespace particles {

void checkTimeStep(double dt, const std::string& where) {
  if (!std::isfinite(dt))
    throw SceneError(where + ": must be a finite number, got " + formatDouble(dt));
  if (!(dt > 0.0)) throw SceneError(where + ": must be > 0, got " + formatDouble(dt));
}

void checkDuration(double duration, const std::string& where) {
  if (!std::isfinite(duration))
    throw SceneError(where + ": must be a finite number, got " + formatDouble(duration));
  if (duration < 0.0) throw SceneError(where + ": must be >= 0, got " + formatDouble(duration));
}

void checkStepCount(double duration, double dt, const std::string& where) {
  // SceneDef::stepCount() is std::llround(duration / dt): defined only below 2^63.
  const double steps = std::round(duration / dt);
  if (!(steps < 0x1p63))
    throw SceneError(where + ": duration / dt = " + formatDouble(duration / dt) +
                     " steps does not fit in the 64-bit step counter (at most 2^63 - 1)");
}

}  // namespace particles
