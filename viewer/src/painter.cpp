#include "particles/viewer/painter.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "particles/viewer/palette.h"

namespace particles::viewer {
namespace {

bool finite(const BallState& b) {
  return b.position.allFinite() && std::isfinite(b.angle);
}

// The closest point of segment ab to p.
Vec2 closestOnSegment(const Vec2& a, const Vec2& b, const Vec2& p) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

// An impulse arrow from the contact point c for a ball of mass m and radius r.
void impulseArrow(DebugDraw& draw, const Vec2& c, const Vec2& impulse, double mass, double radius) {
  Vec2 arrow = impulse / mass * kImpulseArrowSeconds;
  const double cap = kImpulseArrowRadii * radius;
  if (arrow.norm() > cap) arrow *= cap / arrow.norm();
  if (!(arrow.norm() > 0.0)) return;
  drawArrow(draw, c, c + arrow, 0.25 * radius, palette::kImpulse);
}

// The contact's normal segment and the two balls' impulse arrows.
void drawContact(DebugDraw& draw, const SceneDef& scene, const std::vector<BallState>& balls, int a,
                 int b, bool wall, const Vec2& n, const Vec2& impulse) {
  const BallDef& ballA = scene.balls[static_cast<std::size_t>(a)];
  const Vec2 c = balls[static_cast<std::size_t>(a)].position + ballA.radius * n;
  draw.segment(c, c + kNormalRadii * ballA.radius * n, palette::kNormal);
  impulseArrow(draw, c, -impulse, ballA.mass, ballA.radius);
  if (!wall) {
    const BallDef& ballB = scene.balls[static_cast<std::size_t>(b)];
    impulseArrow(draw, c, impulse, ballB.mass, ballB.radius);
  }
}

bool known(const SceneDef& scene, const std::vector<BallState>& balls, int a, int b, bool wall) {
  auto ball = [&](int i) {
    return i >= 0 && static_cast<std::size_t>(i) < std::min(balls.size(), scene.balls.size()) &&
           finite(balls[static_cast<std::size_t>(i)]);
  };
  const bool other = wall ? b >= 0 && static_cast<std::size_t>(b) < scene.walls.size() : ball(b);
  return ball(a) && other;
}

}  // namespace

void drawArrow(DebugDraw& draw, const Vec2& from, const Vec2& to, double head, Color color) {
  const Vec2 d = to - from;
  const double length = d.norm();
  if (!(length > 0.0)) return;
  draw.segment(from, to, color);
  const Vec2 u = d / length;
  const double h = std::min(head, 0.25 * length);
  // Two strokes at +-30 degrees back from the tip.
  const double c = std::cos(std::numbers::pi / 6.0), s = std::sin(std::numbers::pi / 6.0);
  const Vec2 back = -u;
  draw.segment(to, to + h * Vec2(c * back.x() - s * back.y(), s * back.x() + c * back.y()), color);
  draw.segment(to, to + h * Vec2(c * back.x() + s * back.y(), -s * back.x() + c * back.y()), color);
}

void drawWalls(DebugDraw& draw, const SceneDef& scene) {
  for (const WallDef& w : scene.walls) draw.segment(w.a, w.b, palette::kWall);
}

void drawBalls(DebugDraw& draw, const SceneDef& scene, const std::vector<BallState>& balls,
               const BallLook& look) {
  const std::size_t n = std::min(balls.size(), scene.balls.size());
  for (std::size_t i = 0; i < n; ++i) {
    const BallState& b = balls[i];
    if (!finite(b)) continue;
    const double r = scene.balls[i].radius;
    if (look.filled) {
      draw.solidCircle(b.position, r, b.angle, look.color, look.marker);
    } else {
      draw.circle(b.position, r, look.color);
      draw.segment(b.position, b.position + r * Vec2(std::cos(b.angle), std::sin(b.angle)),
                   look.color);
    }
  }
}

void drawPull(DebugDraw& draw, const Vec2& centre, const Vec2& cursor) {
  draw.segment(centre, cursor, palette::kDrag);
  draw.point(cursor, 7.0, palette::kDrag);
}

void drawImpacts(DebugDraw& draw, const SceneDef& scene, const std::vector<BallState>& balls,
                 const std::vector<ImpactEvent>& impacts) {
  for (const ImpactEvent& e : impacts) {
    if (!known(scene, balls, e.a, e.b, e.wall)) continue;
    const Vec2 tau = perpLeft(e.normal);
    drawContact(draw, scene, balls, e.a, e.b, e.wall, e.normal,
                e.normalImpulse * e.normal + e.tangentImpulse * tau);
  }
}

void drawBox2DContacts(DebugDraw& draw, const SceneDef& scene, const std::vector<BallState>& balls,
                       const std::vector<reference::ContactInfo>& contacts) {
  for (const reference::ContactInfo& k : contacts) {
    if (!k.touching || !known(scene, balls, k.a, k.b, k.wall)) continue;
    const Vec2 xa = balls[static_cast<std::size_t>(k.a)].position;
    Vec2 toward;
    if (k.wall) {
      const WallDef& w = scene.walls[static_cast<std::size_t>(k.b)];
      toward = closestOnSegment(w.a, w.b, xa) - xa;
    } else {
      toward = balls[static_cast<std::size_t>(k.b)].position - xa;
    }
    if (!(toward.norm() > 0.0)) continue;
    const Vec2 n = toward.normalized();
    drawContact(draw, scene, balls, k.a, k.b, k.wall, n, k.normalImpulse * n);
  }
}

}  // namespace particles::viewer
