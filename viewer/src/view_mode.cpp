#include "particles/viewer/view_mode.h"

namespace particles::viewer {

std::string_view modeName(ViewMode mode) {
  switch (mode) {
    case ViewMode::Engine:
      return "engine";
    case ViewMode::Box2D:
      return "box2d";
    case ViewMode::Overlay:
      return "overlay";
    case ViewMode::Side:
      return "side";
  }
  return "engine";
}

std::optional<ViewMode> parseMode(std::string_view name) {
  for (ViewMode m : {ViewMode::Engine, ViewMode::Box2D, ViewMode::Overlay, ViewMode::Side})
    if (modeName(m) == name) return m;
  return std::nullopt;
}

ViewMode nextMode(ViewMode mode, bool haveBox2D) {
  if (!haveBox2D) return ViewMode::Engine;
  switch (mode) {
    case ViewMode::Engine:
      return ViewMode::Box2D;
    case ViewMode::Box2D:
      return ViewMode::Overlay;
    case ViewMode::Overlay:
      return ViewMode::Side;
    case ViewMode::Side:
      return ViewMode::Engine;
  }
  return ViewMode::Engine;
}

bool showsEngine(ViewMode mode) {
  return mode != ViewMode::Box2D;
}

bool showsBox2D(ViewMode mode) {
  return mode != ViewMode::Engine;
}

}  // namespace particles::viewer
