#include "particles/viewer/frame.h"

#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/Text.hpp>
#include <filesystem>

#include "particles/viewer/painter.h"
#include "particles/viewer/palette.h"
#include "particles/viewer/readout.h"
#include "particles/viewer/sfml_draw.h"

namespace particles::viewer {
namespace {

constexpr unsigned kTextSize = 14;     // px
constexpr float kLineSpacing = 18.0f;  // px
constexpr float kTextMargin = 6.0f;    // px
// Lines the readout can have (readoutLines: state, two worlds, discrepancy,
// pull), kept free above the scene.
constexpr float kReadoutLines = 5.0f;

void drawTextLines(sf::RenderTarget& target, const sf::Font& font,
                   const std::vector<std::string>& lines, sf::Vector2f topLeft) {
  float width = 0.0f;
  std::vector<sf::Text> texts;
  for (const std::string& line : lines) {
    sf::Text& t = texts.emplace_back(line, font, kTextSize);
    t.setFillColor(toSf(palette::kText));
    width = std::max(width, t.getLocalBounds().width);
  }
  sf::RectangleShape panel(
      {width + 2.0f * kTextMargin, kLineSpacing * static_cast<float>(lines.size()) + kTextMargin});
  panel.setPosition(topLeft);
  panel.setFillColor(toSf(palette::kPanel));
  target.draw(panel);
  for (std::size_t i = 0; i < texts.size(); ++i) {
    texts[i].setPosition(topLeft.x + kTextMargin,
                         topLeft.y + kTextMargin * 0.5f + kLineSpacing * static_cast<float>(i));
    target.draw(texts[i]);
  }
}

// One world (and the pull on it) in one viewport.
void drawWorld(DebugDraw& draw, const Session& session, const FrameOptions& o, bool box2d) {
  const SceneDef& scene = session.scene();
  drawWalls(draw, scene);
  const std::vector<BallState> balls = box2d ? session.box2dBalls() : session.engineBalls();
  drawBalls(draw, scene, balls,
            {true, box2d ? palette::kBox2DBall : palette::kEngineBall, palette::kMarker});
  if (o.mode == ViewMode::Overlay && session.hasBox2D())
    drawBalls(draw, scene, session.box2dBalls(), {false, palette::kBox2DBall, palette::kMarker});
  if (o.contacts) {
    if (box2d)
      drawBox2DContacts(draw, scene, balls, session.box2d()->contacts());
    else
      drawImpacts(draw, scene, balls, session.impacts());
  }
  if (const std::optional<int> held = session.held())
    drawPull(draw, balls.at(static_cast<std::size_t>(*held)).position, session.holdTarget());
}

}  // namespace

std::unique_ptr<sf::Font> loadReadoutFont() {
  // Checked first: sf::Font would print its own error for a missing file.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(kFontPath, ec)) return nullptr;
  auto font = std::make_unique<sf::Font>();
  if (!font->loadFromFile(kFontPath)) return nullptr;
  return font;
}

std::vector<Camera> frameCameras(const Session& session, const FrameOptions& options,
                                 const sf::Vector2u& size, const sf::Font* font) {
  FitInsets insets;
  if (options.readout && font != nullptr) {
    insets.top = kReadoutLines * kLineSpacing + kTextMargin;
    insets.bottom = 2.0f * kLineSpacing + 2.0f * kTextMargin;
  }
  return camerasFor(options.mode, session.viewBounds(), static_cast<int>(size.x),
                    static_cast<int>(size.y), options.control, insets);
}

bool viewportShowsBox2D(ViewMode mode, std::size_t k) {
  return mode == ViewMode::Box2D || (mode == ViewMode::Side && k == 1);
}

void renderFrame(sf::RenderTarget& target, const Session& session, const FrameOptions& o,
                 const sf::Font* font) {
  const sf::Vector2u size = target.getSize();
  // Not getDefaultView(): SFML 2.5 keeps a window's default view at its
  // first size after a resize.
  const sf::View whole =
      clippedPixelView({0, 0, static_cast<int>(size.x), static_cast<int>(size.y)}, size);
  target.setView(whole);
  target.clear(toSf(palette::kBackground));
  const std::vector<Camera> cameras = frameCameras(session, o, size, font);
  for (std::size_t k = 0; k < cameras.size(); ++k) {
    const bool box2d = viewportShowsBox2D(o.mode, k);
    if (box2d && !session.hasBox2D()) continue;
    target.setView(clippedPixelView(cameras[k].viewport, size));
    SfmlDebugDraw draw(target, cameras[k]);
    drawWorld(draw, session, o, box2d);
  }
  target.setView(whole);
  if (o.mode == ViewMode::Side && cameras.size() == 2) {
    sf::RectangleShape divider({1.0f, static_cast<float>(size.y)});
    divider.setPosition(static_cast<float>(cameras[1].viewport.left), 0.0f);
    divider.setFillColor(toSf(palette::kDivider));
    target.draw(divider);
  }
  if (!o.readout || font == nullptr) return;
  drawTextLines(target, *font, readoutLines(session, o.mode), {0.0f, 0.0f});
  if (o.mode == ViewMode::Side && cameras.size() == 2) {
    const float y = static_cast<float>(size.y) - 2.0f * kLineSpacing - 2.0f * kTextMargin;
    drawTextLines(target, *font, {"engine"}, {0.0f, y});
    drawTextLines(target, *font, {"Box2D 2.4.1"},
                  {static_cast<float>(cameras[1].viewport.left) + 1.0f, y});
  }
  const sf::Text full(keyHelpLine(true), *font, kTextSize);
  const bool fits = full.getLocalBounds().width + 2.0f * kTextMargin <= static_cast<float>(size.x);
  drawTextLines(target, *font, {keyHelpLine(fits)},
                {0.0f, static_cast<float>(size.y) - kLineSpacing - kTextMargin});
}

}  // namespace particles::viewer
