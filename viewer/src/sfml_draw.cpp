#include "particles/viewer/sfml_draw.h"

#include <SFML/Graphics/CircleShape.hpp>
#include <SFML/Graphics/RectangleShape.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace particles::viewer {
namespace {

// Enough polygon points for a circle of r px to look round.
std::size_t pointsFor(float radiusPx) {
  return static_cast<std::size_t>(std::clamp(radiusPx, 16.0f, 128.0f));
}

}  // namespace

sf::Color toSf(Color c) {
  return {c.r, c.g, c.b, c.a};
}

float screenDegrees(double angle) {
  return static_cast<float>(-angle * 180.0 / std::numbers::pi);
}

sf::View clippedPixelView(const Viewport& v, const sf::Vector2u& targetSize) {
  const float w = static_cast<float>(std::max(1u, targetSize.x));
  const float h = static_cast<float>(std::max(1u, targetSize.y));
  sf::View view(sf::FloatRect(static_cast<float>(v.left), static_cast<float>(v.top),
                              static_cast<float>(v.width), static_cast<float>(v.height)));
  view.setViewport(sf::FloatRect(static_cast<float>(v.left) / w, static_cast<float>(v.top) / h,
                                 static_cast<float>(v.width) / w,
                                 static_cast<float>(v.height) / h));
  return view;
}

SfmlDebugDraw::SfmlDebugDraw(sf::RenderTarget& target, const Camera& camera, float lineWidth)
    : target_(target), camera_(camera), lineWidth_(lineWidth) {}

sf::Vector2f SfmlDebugDraw::px(const Vec2& world) const {
  const Vec2 s = camera_.toScreen(world);
  return {static_cast<float>(s.x()), static_cast<float>(s.y())};
}

// A line as a thin rectangle from `from`, turned by `degrees` (SFML's sense).
void SfmlDebugDraw::line(const sf::Vector2f& from, float length, float degrees, float width,
                         Color color) {
  sf::RectangleShape bar({length, width});
  bar.setOrigin(0.0f, 0.5f * width);
  bar.setPosition(from);
  bar.setRotation(degrees);
  bar.setFillColor(toSf(color));
  target_.draw(bar);
}

void SfmlDebugDraw::circle(const Vec2& centre, double radius, Color color) {
  const float r = static_cast<float>(radius * camera_.scale);
  sf::CircleShape shape(r, pointsFor(r));
  shape.setOrigin(r, r);
  shape.setPosition(px(centre));
  shape.setFillColor(sf::Color::Transparent);
  // Outside the radius, so that a ghost stays visible around a filled ball of
  // the same size.
  shape.setOutlineThickness(lineWidth_);
  shape.setOutlineColor(toSf(color));
  target_.draw(shape);
}

// The marker is a bar from the centre turned by screenDegrees(angle): the
// handout's rotate(-angle), checked by the viewer tests against the camera's
// own projection of the rim point (cos a, sin a).
void SfmlDebugDraw::solidCircle(const Vec2& centre, double radius, double angle, Color fill,
                                Color marker) {
  const float r = static_cast<float>(radius * camera_.scale);
  sf::CircleShape shape(r, pointsFor(r));
  shape.setOrigin(r, r);
  shape.setPosition(px(centre));
  shape.setFillColor(toSf(fill));
  target_.draw(shape);
  const float width = std::clamp(0.08f * r, lineWidth_, 3.0f * lineWidth_);
  line(px(centre), r, screenDegrees(angle), width, marker);
}

void SfmlDebugDraw::segment(const Vec2& a, const Vec2& b, Color color) {
  const sf::Vector2f pa = px(a), pb = px(b);
  const sf::Vector2f d = pb - pa;
  const float length = std::hypot(d.x, d.y);
  if (!(length > 0.0f)) return;
  // Already in screen coordinates: the angle is measured there, no flip.
  const float degrees = static_cast<float>(std::atan2(d.y, d.x) * 180.0 / std::numbers::pi);
  line(pa, length, degrees, lineWidth_, color);
}

void SfmlDebugDraw::point(const Vec2& p, double sizePixels, Color color) {
  const float s = static_cast<float>(sizePixels);
  sf::RectangleShape dot({s, s});
  dot.setOrigin(0.5f * s, 0.5f * s);
  dot.setPosition(px(p));
  dot.setFillColor(toSf(color));
  target_.draw(dot);
}

}  // namespace particles::viewer
