#include "particles/compare/scene_compare.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

#include "particles/reference/box2d_range.h"
#include "particles/reference/box2d_world.h"
#include "world_velocities.h"

namespace particles::compare {
namespace {

using Key = std::tuple<int, int, bool>;  // (a, b, wall)

template <typename W>
CollisionEvent makeEvent(int a, int b, bool wall, long long step, double dt,
                         const std::vector<BodyVelocity>& before, const W& world) {
  CollisionEvent e{a, b, wall, step, static_cast<double>(step) * dt, {}};
  const BallState sa = world.ball(a);
  e.bodies.push_back({a, before[a], {sa.velocity, sa.angularVelocity}});
  if (!wall) {
    const BallState sb = world.ball(b);
    e.bodies.push_back({b, before[b], {sb.velocity, sb.angularVelocity}});
  }
  return e;
}

MatchedEvent match(const SceneDef& scene, const CollisionEvent& e, const CollisionEvent& b) {
  MatchedEvent m{e, b, 0.0, 0.0, 0.0};
  double scale = 1e-300, worst = 0.0;
  for (std::size_t k = 0; k < e.bodies.size(); ++k) {
    const double r = scene.balls[e.bodies[k].ball].radius;
    const EventBody& x = e.bodies[k];
    const EventBody& y = b.bodies[k];
    // The scale is the bodies' speeds before and after (in both engines), so
    // that an event that starts a resting ball moving has a finite relative
    // difference.
    for (const EventBody* s : {&x, &y})
      for (const BodyVelocity* v : {&s->before, &s->after})
        scale = std::max(scale, v->velocity.norm() + std::abs(v->angularVelocity) * r);
    const double dv = (x.after.velocity - y.after.velocity).norm();
    const double dw = std::abs(x.after.angularVelocity - y.after.angularVelocity);
    m.velocityDifference = std::max(m.velocityDifference, dv);
    m.spinDifference = std::max(m.spinDifference, dw);
    worst = std::max({worst, dv, dw * r});
  }
  m.relative = worst / scale;
  return m;
}

nlohmann::json bodyJson(const EventBody& b) {
  auto v = [](const BodyVelocity& x) {
    return nlohmann::json{{"velocity", {x.velocity.x(), x.velocity.y()}},
                          {"angular_velocity", x.angularVelocity}};
  };
  return {{"ball", b.ball}, {"before", v(b.before)}, {"after", v(b.after)}};
}

nlohmann::json eventJson(const CollisionEvent& e) {
  nlohmann::json bodies = nlohmann::json::array();
  for (const EventBody& b : e.bodies) bodies.push_back(bodyJson(b));
  return {{"a", e.a},       {"b", e.b},       {"wall", e.wall},
          {"step", e.step}, {"time", e.time}, {"bodies", bodies}};
}

std::string pairName(const CollisionEvent& e) {
  return "balls[" + std::to_string(e.a) + "]-" + (e.wall ? "walls[" : "balls[") +
         std::to_string(e.b) + "]";
}

}  // namespace

SceneComparison compareScene(const SceneDef& scene, const std::string& label,
                             const CompareSettings& settings) {
  SceneComparison out;
  out.scene = label;
  out.steps = scene.stepCount();
  reference::Box2DSettings b2 = settings.box2d;
  b2.dt = scene.dt;
  for (const reference::RangeIssue& issue : reference::checkBox2DRange(scene, b2))
    out.rangeIssues.push_back(issue.message);

  World engine(scene);
  engine.recordImpacts(true);
  reference::Box2DWorld box2d(scene, b2);
  std::map<Key, std::vector<CollisionEvent>> engineEvents, box2dEvents;

  for (long long step = 0; step < out.steps; ++step) {
    const std::vector<BodyVelocity> engineBefore = detail::velocitiesOf(engine);
    const std::vector<BodyVelocity> box2dBefore = detail::velocitiesOf(box2d);
    engine.step();
    box2d.step();
    for (const ImpactEvent& i : engine.impacts())
      engineEvents[{i.a, i.b, i.wall}].push_back(
          makeEvent(i.a, i.b, i.wall, step, scene.dt, engineBefore, engine));
    for (const reference::ContactInfo& c : box2d.contacts())
      if (c.touching && c.normalImpulse > 0.0)
        box2dEvents[{c.a, c.b, c.wall}].push_back(
            makeEvent(c.a, c.b, c.wall, step, scene.dt, box2dBefore, box2d));
  }

  // Per pair, walk both time-ordered lists together: events within the
  // window are the same collision; otherwise the earlier one is unmatched.
  std::map<Key, bool> keys;
  for (const auto& [k, _] : engineEvents) keys[k] = true;
  for (const auto& [k, _] : box2dEvents) keys[k] = true;
  for (const auto& [key, _] : keys) {
    const auto& es = engineEvents[key];
    const auto& bs = box2dEvents[key];
    std::size_t i = 0, j = 0;
    while (i < es.size() || j < bs.size()) {
      if (j == bs.size() ||
          (i < es.size() && es[i].step + settings.matchWindowSteps < bs[j].step)) {
        out.engineOnly.push_back(es[i++]);
      } else if (i == es.size() || bs[j].step + settings.matchWindowSteps < es[i].step) {
        out.box2dOnly.push_back(bs[j++]);
      } else {
        out.matched.push_back(match(scene, es[i++], bs[j++]));
        out.worstRelative = std::max(out.worstRelative, out.matched.back().relative);
      }
    }
  }
  auto byTime = [](const auto& x, const auto& y) { return x.step < y.step; };
  std::stable_sort(
      out.matched.begin(), out.matched.end(),
      [](const MatchedEvent& x, const MatchedEvent& y) { return x.engine.step < y.engine.step; });
  std::stable_sort(out.engineOnly.begin(), out.engineOnly.end(), byTime);
  std::stable_sort(out.box2dOnly.begin(), out.box2dOnly.end(), byTime);

  for (std::size_t i = 0; i < engine.ballCount(); ++i) {
    out.engineFinal.push_back(engine.ball(i));
    out.box2dFinal.push_back(box2d.ball(i));
  }
  return out;
}

nlohmann::json comparisonJson(const SceneComparison& c) {
  nlohmann::json matched = nlohmann::json::array(), eo = nlohmann::json::array(),
                 bo = nlohmann::json::array();
  for (const MatchedEvent& m : c.matched)
    matched.push_back({{"engine", eventJson(m.engine)},
                       {"box2d", eventJson(m.box2d)},
                       {"difference",
                        {{"velocity", m.velocityDifference},
                         {"spin", m.spinDifference},
                         {"relative", m.relative}}}});
  for (const CollisionEvent& e : c.engineOnly) eo.push_back(eventJson(e));
  for (const CollisionEvent& e : c.box2dOnly) bo.push_back(eventJson(e));
  nlohmann::json finals = nlohmann::json::array();
  for (std::size_t i = 0; i < c.engineFinal.size(); ++i) {
    const BallState& e = c.engineFinal[i];
    const BallState& b = c.box2dFinal[i];
    finals.push_back(
        {{"ball", i},
         {"position_difference", (e.position - b.position).norm()},
         {"velocity_difference", (e.velocity - b.velocity).norm()},
         {"angular_velocity_difference", std::abs(e.angularVelocity - b.angularVelocity)}});
  }
  return {{"scene", c.scene},
          {"steps", c.steps},
          {"outside_box2d_range", c.rangeIssues},
          {"worst_relative_difference", c.worstRelative},
          {"matched", matched},
          {"engine_only", eo},
          {"box2d_only", bo},
          {"final", finals}};
}

std::string comparisonText(const SceneComparison& c) {
  std::ostringstream s;
  s << c.scene << ": " << c.steps << " steps, " << c.matched.size() << " matched collision events, "
    << c.engineOnly.size() << " engine only, " << c.box2dOnly.size() << " Box2D only\n";
  for (const std::string& r : c.rangeIssues) s << "  outside Box2D's range: " << r << "\n";
  const MatchedEvent* worst = nullptr;
  for (const MatchedEvent& m : c.matched)
    if (!worst || m.relative > worst->relative) worst = &m;
  if (worst) {
    s << "  largest post-collision difference: " << pairName(worst->engine)
      << " at t = " << worst->engine.time << " s: |dv| = " << worst->velocityDifference
      << " m/s, |dw| = " << worst->spinDifference << " rad/s (relative " << worst->relative
      << ")\n";
  }
  int shown = 0;
  for (const CollisionEvent& e : c.engineOnly)
    if (shown++ < 5) s << "  engine only: " << pairName(e) << " at t = " << e.time << " s\n";
  shown = 0;
  for (const CollisionEvent& e : c.box2dOnly)
    if (shown++ < 5) s << "  Box2D only: " << pairName(e) << " at t = " << e.time << " s\n";
  return s.str();
}

}  // namespace particles::compare
