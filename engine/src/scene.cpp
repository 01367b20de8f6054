#include "particles/scene.h"

#include <cmath>

namespace particles {

std::vector<WallDef> boxWalls(const Vec2& lo, const Vec2& hi) {
  const Vec2 lr(hi.x(), lo.y()), ul(lo.x(), hi.y());
  auto wall = [](const Vec2& a, const Vec2& b) {
    WallDef w;
    w.a = a;
    w.b = b;
    w.oneSided = true;  // counter-clockwise: the inside is on each wall's left
    return w;
  };
  return {wall(lo, lr), wall(lr, hi), wall(hi, ul), wall(ul, lo)};
}

long long SceneDef::stepCount() const {
  return std::llround(duration / dt);
}

}  // namespace particles
