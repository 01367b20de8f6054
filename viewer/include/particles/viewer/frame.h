// One picture of a session: the worlds of the current mode in their
// viewports, the pull, optional contacts, and the readout. The same code
// draws into the window and into the off-screen texture of a screenshot.
#pragma once

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <memory>
#include <vector>

#include "particles/viewer/camera.h"
#include "particles/viewer/session.h"
#include "particles/viewer/view_mode.h"

namespace particles::viewer {

// What the user chose to see; changes nothing in the physics.
struct FrameOptions {
  ViewMode mode = ViewMode::Side;
  bool contacts = false;  // contact normals and impulses (key D)
  bool readout = true;    // the text readout, when there is a font
  CameraControl control;  // pan and zoom
};

// The font of the readout, DejaVu Sans from Debian's fonts-dejavu-core;
// null when it is not installed (the viewer then draws no text).
inline constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
std::unique_ptr<sf::Font> loadReadoutFont();

// The cameras of the frame for a target of `size`, in viewport order. With
// the readout shown (options.readout and a font) the scene is fitted below
// it and above the key line; without, into the whole viewport.
std::vector<Camera> frameCameras(const Session& session, const FrameOptions& options,
                                 const sf::Vector2u& size, const sf::Font* font);

// `mode`, or Engine with a warning on stderr when `mode` needs the Box2D
// twin and the session has none.
ViewMode usableMode(ViewMode mode, const Session& session);

// Which world viewport k of `mode` shows: true for Box2D's.
bool viewportShowsBox2D(ViewMode mode, std::size_t k);

// Clears `target` and draws the frame. `font` may be null.
void renderFrame(sf::RenderTarget& target, const Session& session, const FrameOptions& options,
                 const sf::Font* font);

}  // namespace particles::viewer
