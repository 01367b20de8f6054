// DebugDraw on an SFML render target (a window or an off-screen texture):
// world coordinates go through a Camera into pixels.
#pragma once

#include <SFML/Graphics/Color.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/View.hpp>

#include "particles/viewer/camera.h"
#include "particles/viewer/debug_draw.h"

namespace particles::viewer {

sf::Color toSf(Color c);

// The rotation, in SFML's degrees, that shows a world angle (rad,
// counter-clockwise, y up) on screen. SFML's y axis points down, so its
// positive rotation is clockwise on screen: a world angle a is -a there (the
// handout's sprite.rotate(-angle)).
float screenDegrees(double angle);

// A view that maps the target's pixels 1:1 but draws only inside `viewport`,
// so that side-by-side worlds do not spill into each other.
sf::View clippedPixelView(const Viewport& viewport, const sf::Vector2u& targetSize);

class SfmlDebugDraw final : public DebugDraw {
 public:
  // Lines are `lineWidth` px wide. Draws through the target's current view,
  // which must map pixels 1:1 (clippedPixelView or the default view).
  SfmlDebugDraw(sf::RenderTarget& target, const Camera& camera, float lineWidth = 2.0f);

  void circle(const Vec2& centre, double radius, Color color) override;
  void solidCircle(const Vec2& centre, double radius, double angle, Color fill,
                   Color marker) override;
  void segment(const Vec2& a, const Vec2& b, Color color) override;
  void point(const Vec2& p, double sizePixels, Color color) override;

 private:
  sf::Vector2f px(const Vec2& world) const;
  void line(const sf::Vector2f& from, float length, float degrees, float width, Color color);

  sf::RenderTarget& target_;
  Camera camera_;
  float lineWidth_;
};

}  // namespace particles::viewer
