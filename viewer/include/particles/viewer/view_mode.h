// What the viewer shows: one engine, the other, or both (key M cycles).
#pragma once

#include <optional>
#include <string_view>

namespace particles::viewer {

enum class ViewMode {
  Engine,   // the engine's balls only
  Box2D,    // the Box2D twin's balls only
  Overlay,  // the engine's balls, Box2D's as outlined ghosts on top
  Side,     // two viewports: engine on the left, Box2D on the right
};

// "engine", "box2d", "overlay", "side": the names of --mode.
std::string_view modeName(ViewMode mode);
std::optional<ViewMode> parseMode(std::string_view name);

// The next mode in the order above, wrapping; Engine only when there is no
// Box2D twin to show.
ViewMode nextMode(ViewMode mode, bool haveBox2D);

// Which worlds a mode draws.
bool showsEngine(ViewMode mode);
bool showsBox2D(ViewMode mode);

}  // namespace particles::viewer
