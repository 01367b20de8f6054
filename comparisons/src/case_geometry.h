// The contact frame of an isolated case, written out here rather than
// borrowed from the engine, so that the judges of the engine share no code
// with it.
#pragma once

#include <algorithm>

#include "particles/compare/impact_case.h"

namespace particles::compare::detail {

struct ContactFrame {
  Vec2 normal{1.0, 0.0};  // unit, from ball a to body b
  Vec2 point{0.0, 0.0};   // m, a's surface point: x_a + r_a n
  double overlap = 0.0;   // m, how far the surfaces interpenetrate
  bool wall = false;      // body b is walls[0]
};

inline ContactFrame contactFrame(const ImpactCase& c) {
  const BallDef& a = c.scene.balls[0];
  ContactFrame f;
  f.wall = c.scene.balls.size() == 1;
  if (f.wall) {
    const WallDef& w = c.scene.walls[0];
    const Vec2 ab = w.b - w.a;
    const double s = std::clamp((a.position - w.a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    const Vec2 d = w.a + s * ab - a.position;
    f.normal = d.normalized();
    f.overlap = a.radius - d.norm();
  } else {
    const Vec2 d = c.scene.balls[1].position - a.position;
    f.normal = d.normalized();
    f.overlap = a.radius + c.scene.balls[1].radius - d.norm();
  }
  f.point = a.position + a.radius * f.normal;
  return f;
}

// The material at the isolated contact, with the scene's mixing rules.
inline ContactMaterial contactMaterial(const ImpactCase& c) {
  const SceneDef& s = c.scene;
  const BallDef& a = s.balls[0];
  const ContactMaterial ma = resolveMaterial(s.contact, a.restitution, a.friction);
  if (s.balls.size() == 1)
    return mixMaterials(ma,
                        resolveMaterial(s.contact, s.walls[0].restitution, s.walls[0].friction));
  const BallDef& b = s.balls[1];
  return mixMaterials(ma, resolveMaterial(s.contact, b.restitution, b.friction));
}

}  // namespace particles::compare::detail
