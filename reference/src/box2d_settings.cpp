#include "particles/reference/box2d_settings.h"

namespace particles::reference {

Box2DSettings Box2DSettings::forScene(const SceneDef& scene) {
  Box2DSettings settings;
  settings.dt = scene.dt;
  return settings;
}

}  // namespace particles::reference
