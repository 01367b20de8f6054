// The headless run: a fixed number of 60 Hz frames, then one picture drawn
// off screen and saved as PNG. Deterministic: no clock is read.
#include <SFML/Graphics/Image.hpp>
#include <SFML/Graphics/RenderTexture.hpp>
#include <iostream>

#include "particles/viewer/frame.h"
#include "particles/viewer/session.h"
#include "particles/viewer/viewer_app.h"

namespace particles::viewer {

int runHeadless(const SceneDef& scene, const ViewOptions& o) {
  Session session(scene);
  if (o.drag) session.hold(o.drag->ball, o.drag->target);
  for (long long f = 0; f < o.frames; ++f) session.advance(kFrameSeconds);

  sf::RenderTexture texture;
  if (!texture.create(static_cast<unsigned>(o.width), static_cast<unsigned>(o.height))) {
    std::cerr << "particles: error: cannot create an off-screen OpenGL surface of " << o.width
              << "x" << o.height << " px\n";
    return 1;
  }
  FrameOptions frame;
  frame.mode = usableMode(o.mode, session);
  frame.readout = o.readout;
  frame.contacts = o.contacts;
  const std::unique_ptr<sf::Font> font = loadReadoutFont();
  renderFrame(texture, session, frame, font.get());
  texture.display();
  if (!texture.getTexture().copyToImage().saveToFile(o.screenshot)) {
    std::cerr << "particles: error: --screenshot: cannot write '" << o.screenshot << "'\n";
    return 1;
  }
  std::cout << "particles: wrote " << o.screenshot << " (" << o.width << "x" << o.height
            << " px, t = " << session.engine().time() << " s, mode " << modeName(o.mode) << ")\n";
  return 0;
}

}  // namespace particles::viewer
