// Run time against error: the Pareto front of a sweep and the speed ratio of
// two fronts at equal error (docs/bench.md, "Equal error").
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace particles::timestep {

// Errors below this are rounding: they are floored to it before any
// logarithm, so that an exact answer (error 0) still has a place on a
// log-log plot and the interpolation stays finite.
inline constexpr double kErrorFloor = 1e-16;

struct CostPoint {
  double seconds = 0.0;   // wall time per simulated second (s/s)
  double error = 0.0;     // dimensionless; +inf for a diverged run
  std::size_t index = 0;  // the caller's index of this configuration
};

// The points no other point beats: none has both seconds <= and error <=
// (with one strictly smaller). Sorted by seconds ascending, so errors
// strictly decrease. Points with a non-finite error never belong to it.
std::vector<CostPoint> paretoFront(std::vector<CostPoint> points);

// The wall time a front needs to reach `error`: log-log interpolation between
// the two front points that bracket it. Above the front's largest error, the
// cheapest point's time (`clamped` says so); below its smallest error,
// nullopt (this engine never got that accurate in the sweep).
struct TimeAtError {
  double seconds = 0.0;
  bool clamped = false;
};
std::optional<TimeAtError> timeAtError(const std::vector<CostPoint>& front, double error);

// At equal error: the tightest error both fronts reach (the larger of their
// smallest errors), and Box2D's time over the engine's there. > 1 means the
// engine is faster. `lowerBound` when either time was clamped (one front
// never was that inaccurate, so its real time there could only be lower):
// the ratio is then a bound, not a measurement. Empty fronts give nullopt.
struct EqualErrorRatio {
  double error = 0.0;
  double engineSeconds = 0.0, box2dSeconds = 0.0;
  double ratio = 0.0;  // box2dSeconds / engineSeconds
  bool engineClamped = false, box2dClamped = false;
};
std::optional<EqualErrorRatio> equalErrorRatio(const std::vector<CostPoint>& engineFront,
                                               const std::vector<CostPoint>& box2dFront);

}  // namespace particles::timestep
