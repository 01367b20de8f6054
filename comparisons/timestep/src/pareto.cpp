#include "particles/timestep/pareto.h"

#include <algorithm>
#include <cmath>

namespace particles::timestep {

std::vector<CostPoint> paretoFront(std::vector<CostPoint> points) {
  std::erase_if(points, [](const CostPoint& p) { return !std::isfinite(p.error); });
  std::sort(points.begin(), points.end(), [](const CostPoint& a, const CostPoint& b) {
    return a.seconds != b.seconds ? a.seconds < b.seconds : a.error < b.error;
  });
  std::vector<CostPoint> front;
  for (const CostPoint& p : points)
    if (front.empty() || p.error < front.back().error) front.push_back(p);
  return front;
}

std::optional<TimeAtError> timeAtError(const std::vector<CostPoint>& front, double error) {
  if (front.empty()) return std::nullopt;
  const double e = std::max(error, kErrorFloor);
  if (e >= std::max(front.front().error, kErrorFloor))
    return TimeAtError{front.front().seconds, e > std::max(front.front().error, kErrorFloor)};
  for (std::size_t i = 1; i < front.size(); ++i) {
    const double hi = std::max(front[i - 1].error, kErrorFloor);
    const double lo = std::max(front[i].error, kErrorFloor);
    if (e < lo) continue;
    if (hi == lo) return TimeAtError{front[i].seconds, false};
    // Straight line in (log error, log time) between the two points.
    const double f = (std::log(hi) - std::log(e)) / (std::log(hi) - std::log(lo));
    const double lt = std::log(front[i - 1].seconds) +
                      f * (std::log(front[i].seconds) - std::log(front[i - 1].seconds));
    return TimeAtError{std::exp(lt), false};
  }
  return std::nullopt;
}

std::optional<EqualErrorRatio> equalErrorRatio(const std::vector<CostPoint>& engineFront,
                                               const std::vector<CostPoint>& box2dFront) {
  if (engineFront.empty() || box2dFront.empty()) return std::nullopt;
  const double error = std::max({engineFront.back().error, box2dFront.back().error, kErrorFloor});
  const auto te = timeAtError(engineFront, error), tb = timeAtError(box2dFront, error);
  if (!te || !tb) return std::nullopt;
  EqualErrorRatio r;
  r.error = error;
  r.engineSeconds = te->seconds;
  r.box2dSeconds = tb->seconds;
  r.ratio = tb->seconds / te->seconds;
  r.engineClamped = te->clamped;
  r.box2dClamped = tb->clamped;
  return r;
}

}  // namespace particles::timestep
