#include "particles/compare/outcome.h"

#include <algorithm>
#include <cmath>

#include "particles/reference/box2d_world.h"
#include "particles/truth/closed_form.h"

#include "case_geometry.h"
#include "particles/world.h"
#include "world_velocities.h"

namespace particles::compare {
namespace {

bool allFinite(const Outcome& o) {
  return std::all_of(o.balls.begin(), o.balls.end(), [](const BodyVelocity& b) {
    return b.velocity.allFinite() && std::isfinite(b.angularVelocity);
  });
}

truth::Body truthBody(const BallDef& b, const BodyVelocity& v, double leverArm) {
  truth::Body t;
  t.mass = b.mass;
  t.inertia = b.resolvedInertia();
  t.radius = leverArm;
  t.vx = v.velocity.x();
  t.vy = v.velocity.y();
  t.w = v.angularVelocity;
  return t;
}

BodyVelocity fromTruth(const truth::Body& t) {
  return {Vec2(static_cast<double>(t.vx), static_cast<double>(t.vy)), static_cast<double>(t.w)};
}

enum class TruthVariant { Surface, MidOverlap };

std::optional<Outcome> solveTruth(const ImpactCase& c, TruthVariant variant) {
  if (!c.isolated) return std::nullopt;
  const SceneDef& s = c.scene;
  thread_local Outcome before;  // reused per thread: no allocation per case
  initialState(c, before);
  const BallDef& a = s.balls[0];
  const detail::ContactFrame frame = detail::contactFrame(c);
  const ContactMaterial m = detail::contactMaterial(c);
  const Vec2& n = frame.normal;
  const bool wall = frame.wall;
  // Box2D's contact point sits in the middle of the overlap, half-way
  // between the two surfaces: each lever arm is shortened by half of it. The
  // twin's walls have no skin (docs/box2d-twin.md), so the same holds there.
  const double shorten = variant == TruthVariant::MidOverlap ? 0.5 * frame.overlap : 0.0;
  const double e = m.restitution;

  const truth::Body ta = truthBody(a, before.balls[0], a.radius - shorten);
  truth::Body tb;
  if (wall) {
    tb.wall = true;
  } else {
    tb = truthBody(s.balls[1], before.balls[1], s.balls[1].radius - shorten);
  }
  const truth::Impact impact = truth::solveImpact(ta, tb, n.x(), n.y(), e, m.friction);
  Outcome out;
  out.balls.push_back(fromTruth(impact.a));
  if (!wall) out.balls.push_back(fromTruth(impact.b));
  out.finite = allFinite(out);
  return out;
}

}  // namespace

std::string_view sourceName(Source s) {
  switch (s) {
    case Source::Engine:
      return "engine";
    case Source::Box2D:
      return "box2d";
    case Source::Truth:
      return "truth";
  }
  return "unknown";
}

void initialState(const ImpactCase& c, Outcome& out) {
  out.balls.clear();
  for (const BallDef& b : c.scene.balls) out.balls.push_back({b.velocity, b.angularVelocity});
  out.finite = true;
}

Outcome initialState(const ImpactCase& c) {
  Outcome o;
  initialState(c, o);
  return o;
}

Outcome runEngine(const ImpactCase& c, Mutation mutation) {
  // One world per thread, reset for each case (World::reset reuses storage).
  thread_local std::optional<World> world;
  if (mutation == Mutation::None) {
    world ? world->reset(c.scene) : void(world.emplace(c.scene));
  } else {
    SceneDef scene = c.scene;
    scene.solver.mutation = mutation;
    world ? world->reset(scene) : void(world.emplace(scene));
  }
  world->step();
  Outcome o{detail::velocitiesOf(*world), true};
  o.finite = allFinite(o);
  return o;
}

Outcome runBox2D(const ImpactCase& c, const reference::Box2DSettings& settings) {
  // One world per thread, rebuilt in place for each case: reset() is
  // bit-identical to a fresh world and saves its allocations.
  thread_local std::optional<reference::Box2DWorld> world;
  if (world && world->settings() == settings) {
    world->reset(c.scene);
  } else {
    world.emplace(c.scene, settings);
  }
  world->step();
  Outcome o{detail::velocitiesOf(*world), true};
  o.finite = allFinite(o);
  return o;
}

std::optional<Outcome> runTruth(const ImpactCase& c) {
  return solveTruth(c, TruthVariant::Surface);
}

std::optional<Outcome> runTruthMidOverlap(const ImpactCase& c) {
  return solveTruth(c, TruthVariant::MidOverlap);
}

}  // namespace particles::compare
