// Rotation stays right-handed on screen. The marker is an SFML shape turned
// by screenDegrees(angle) (the handout's sprite.rotate(-angle)); it must end
// where the camera projects the world rim point x + r (cos a, sin a), and a
// growing angle must turn it counter-clockwise on screen. sf::Transform is
// plain arithmetic: no window or OpenGL context is needed.
#include <gtest/gtest.h>
#include <SFML/Graphics/Transform.hpp>

#include <cmath>
#include <numbers>

#include "particles/viewer/camera.h"
#include "particles/viewer/sfml_draw.h"

namespace particles::viewer {
namespace {

// Where SFML draws the tip of a marker of length r px turned by `degrees`
// about the screen point `centre`.
Vec2 sfmlTip(const Vec2& centre, double lengthPx, float degrees) {
  sf::Transform t;
  t.translate(static_cast<float>(centre.x()), static_cast<float>(centre.y()));
  t.rotate(degrees);
  const sf::Vector2f tip = t.transformPoint(static_cast<float>(lengthPx), 0.0f);
  return {tip.x, tip.y};
}

// The angle of a screen direction as a person reads it: counter-clockwise
// from the right, with screen y pointing down.
double screenAngle(const Vec2& d) {
  return std::atan2(-d.y(), d.x());
}

TEST(ScreenRotation, MarkerTipIsTheProjectedRimPoint) {
  Camera c;
  c.centre = {0.5, -0.25};
  c.scale = 80.0;
  c.viewport = {0, 0, 640, 480};
  const Vec2 x(1.0, 0.5);
  const double r = 0.4;
  for (double a = -7.0; a <= 7.0; a += 0.25) {
    const Vec2 rim = c.toScreen(x + r * Vec2(std::cos(a), std::sin(a)));
    const Vec2 tip = sfmlTip(c.toScreen(x), r * c.scale, screenDegrees(a));
    EXPECT_LT((tip - rim).norm(), 1e-3) << "angle " << a;
  }
}

TEST(ScreenRotation, QuarterTurnPointsUp) {
  const Vec2 tip = sfmlTip({100.0, 100.0}, 10.0, screenDegrees(std::numbers::pi / 2.0));
  EXPECT_NEAR(tip.x(), 100.0, 1e-4);
  EXPECT_NEAR(tip.y(), 90.0, 1e-4);  // up on screen is smaller y
}

TEST(ScreenRotation, PositiveSpinTurnsCounterClockwiseOnScreen) {
  // A ball with w > 0: its angle grows, and so does the angle of its marker
  // as seen on screen, by the same amount.
  double previous = screenAngle(sfmlTip({0.0, 0.0}, 1.0, screenDegrees(0.0)));
  for (int k = 1; k <= 12; ++k) {
    const double a = 0.25 * k;
    const double seen = screenAngle(sfmlTip({0.0, 0.0}, 1.0, screenDegrees(a)));
    double turned = seen - previous;
    turned -= 2.0 * std::numbers::pi * std::round(turned / (2.0 * std::numbers::pi));
    EXPECT_NEAR(turned, 0.25, 1e-5);
    previous = seen;
  }
}

}  // namespace
}  // namespace particles::viewer
