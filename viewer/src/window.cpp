// The interactive window: Box2D testbed keys, mouse pull, zoom and pan. The
// physics advances by the measured frame time through the session's
// accumulator; nothing here touches dt.
#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/Texture.hpp>
#include <SFML/Window/Event.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <utility>

#include "particles/viewer/frame.h"
#include "particles/viewer/session.h"
#include "particles/viewer/viewer_app.h"

namespace particles::viewer {
namespace {

// s: the most real time one frame may hand to the physics, so that a stalled
// frame (a dragged window, a debugger) does not make the next one run for
// ever trying to catch up.
constexpr double kMaxFrameSeconds = 0.1;
// Zoom factor per wheel notch.
constexpr double kWheelZoom = 1.15;

Vec2 toVec2(int x, int y) {
  return {static_cast<double>(x), static_cast<double>(y)};
}

// "particles-view-N.png" with the first N not taken, in the working directory.
std::string nextScreenshotName() {
  for (int n = 1;; ++n) {
    const std::string name = "particles-view-" + std::to_string(n) + ".png";
    std::error_code ec;
    if (!std::filesystem::exists(name, ec)) return name;
  }
}

void saveScreenshot(const sf::RenderWindow& window) {
  sf::Texture texture;
  if (!texture.create(window.getSize().x, window.getSize().y)) return;
  texture.update(window);
  const std::string name = nextScreenshotName();
  if (texture.copyToImage().saveToFile(name))
    std::cerr << "particles: screenshot saved to " << name << '\n';
  else
    std::cerr << "particles: warning: cannot write the screenshot '" << name << "'\n";
}

// The mouse and the keys: what a user does to the session and the view.
class Controls {
 public:
  Controls(sf::RenderWindow& window, Session& session, FrameOptions& frame, const sf::Font* font)
      : window_(window), session_(session), frame_(frame), font_(font) {}

  void handle(const sf::Event& e) {
    switch (e.type) {
      case sf::Event::Closed:
        window_.close();
        break;
      case sf::Event::KeyPressed:
        key(e.key.code);
        break;
      case sf::Event::MouseButtonPressed:
        press(e.mouseButton.button, toVec2(e.mouseButton.x, e.mouseButton.y));
        break;
      case sf::Event::MouseButtonReleased:
        if (e.mouseButton.button == sf::Mouse::Left) release();
        if (e.mouseButton.button == sf::Mouse::Right) panning_ = false;
        break;
      case sf::Event::MouseMoved:
        move(toVec2(e.mouseMove.x, e.mouseMove.y));
        break;
      case sf::Event::MouseWheelScrolled:
        wheel(e.mouseWheelScroll.delta, toVec2(e.mouseWheelScroll.x, e.mouseWheelScroll.y));
        break;
      default:
        break;
    }
  }

 private:
  std::vector<Camera> cameras() const {
    return frameCameras(session_, frame_, window_.getSize(), font_);
  }

  std::optional<std::size_t> viewportAt(const Vec2& screen) const {
    const std::vector<Camera> all = cameras();
    for (std::size_t k = 0; k < all.size(); ++k)
      if (all[k].contains(screen)) return k;
    return std::nullopt;
  }

  void key(sf::Keyboard::Key code) {
    switch (code) {
      case sf::Keyboard::Escape:
        window_.close();
        break;
      case sf::Keyboard::P:
        session_.setPaused(!session_.paused());
        break;
      case sf::Keyboard::O:  // as in Box2D's testbed: pause, then one step
        session_.setPaused(true);
        session_.stepOnce();
        break;
      case sf::Keyboard::R:
        session_.restart();
        holdViewport_ = kNone;
        break;
      case sf::Keyboard::M:
        frame_.mode = nextMode(frame_.mode, session_.hasBox2D());
        release();
        break;
      case sf::Keyboard::D:
        frame_.contacts = !frame_.contacts;
        break;
      case sf::Keyboard::H:
        frame_.readout = !frame_.readout;
        break;
      case sf::Keyboard::Add:
      case sf::Keyboard::Equal:  // the + key without shift
        session_.faster();
        break;
      case sf::Keyboard::Subtract:
      case sf::Keyboard::Hyphen:
        session_.slower();
        break;
      case sf::Keyboard::F12:
        screenshotWanted_ = true;
        break;
      default:
        break;
    }
  }

  // Left: hold the ball under the cursor, in the world of that viewport.
  // Right: start panning.
  void press(sf::Mouse::Button button, const Vec2& screen) {
    if (button == sf::Mouse::Right) {
      panning_ = true;
      lastMouse_ = screen;
      return;
    }
    if (button != sf::Mouse::Left) return;
    const std::optional<std::size_t> k = viewportAt(screen);
    if (!k) return;
    const Camera camera = cameras()[*k];
    const bool box2d = viewportShowsBox2D(frame_.mode, *k);
    const Vec2 world = camera.toWorld(screen);
    const std::optional<int> ball =
        pickBall(box2d ? session_.box2dBalls() : session_.engineBalls(), session_.scene(), world);
    if (!ball) return;
    session_.hold(*ball, world);
    holdViewport_ = static_cast<int>(*k);
  }

  void release() {
    session_.release();
    holdViewport_ = kNone;
  }

  void move(const Vec2& screen) {
    if (panning_) {
      if (const std::optional<std::size_t> k = viewportAt(screen))
        panBy(frame_.control, cameras()[*k], screen - lastMouse_);
      lastMouse_ = screen;
    }
    if (holdViewport_ != kNone && session_.held())
      session_.moveHold(cameras().at(static_cast<std::size_t>(holdViewport_)).toWorld(screen));
  }

  void wheel(float delta, const Vec2& screen) {
    const std::optional<std::size_t> k = viewportAt(screen);
    if (!k) return;
    zoomAt(frame_.control, cameras()[*k], screen, std::pow(kWheelZoom, static_cast<double>(delta)));
    // The cursor's world point is unchanged by construction, so is the pull.
  }

 public:
  // F12 is honoured after the frame is drawn, so the file shows that frame.
  bool takeScreenshotRequest() { return std::exchange(screenshotWanted_, false); }

 private:
  sf::RenderWindow& window_;
  Session& session_;
  FrameOptions& frame_;
  const sf::Font* font_;
  // The viewport where the held ball was picked: its camera maps the cursor.
  // An int, not an optional: GCC 12 warns (falsely) that an optional member
  // may be used uninitialized.
  static constexpr int kNone = -1;
  int holdViewport_ = kNone;
  bool panning_ = false;
  Vec2 lastMouse_{0.0, 0.0};
  bool screenshotWanted_ = false;
};

}  // namespace

int runWindow(const SceneDef& scene, const ViewOptions& o) {
  Session session(scene);
  FrameOptions frame;
  frame.mode = usableMode(o.mode, session);
  frame.readout = o.readout;
  frame.contacts = o.contacts;
  if (o.drag) session.hold(o.drag->ball, o.drag->target);

  sf::ContextSettings context;
  context.antialiasingLevel = 4;
  const std::string title = "particles view" + (scene.name.empty() ? "" : " - " + scene.name);
  sf::RenderWindow window(
      sf::VideoMode(static_cast<unsigned>(o.width), static_cast<unsigned>(o.height)), title,
      sf::Style::Default, context);
  if (!window.isOpen()) {
    std::cerr << "particles: error: cannot open a window\n";
    return 1;
  }
  window.setFramerateLimit(60);
  const std::unique_ptr<sf::Font> font = loadReadoutFont();
  Controls controls(window, session, frame, font.get());

  sf::Clock clock;
  long long frames = 0;
  while (window.isOpen()) {
    sf::Event event;
    while (window.pollEvent(event)) controls.handle(event);
    if (!window.isOpen()) break;
    session.advance(std::min(static_cast<double>(clock.restart().asSeconds()), kMaxFrameSeconds));
    renderFrame(window, session, frame, font.get());
    if (controls.takeScreenshotRequest()) saveScreenshot(window);
    window.display();
    if (o.frames > 0 && ++frames >= o.frames) window.close();
  }
  return 0;
}

}  // namespace particles::viewer
