#include <iostream>

#include "particles/viewer/frame.h"

namespace particles::viewer {

ViewMode usableMode(ViewMode mode, const Session& session) {
  if (mode == ViewMode::Engine || session.hasBox2D()) return mode;
  std::cerr << "particles: warning: no Box2D twin (" << session.box2dError()
            << "): showing the engine only\n";
  return ViewMode::Engine;
}

}  // namespace particles::viewer
