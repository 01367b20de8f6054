#include "particles/timestep/stress.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>

#include "ball_def.h"

namespace particles::timestep {
namespace {

std::string percent(double x) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3g %%", 100.0 * x);
  return buf;
}

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

// Ball 0 started left of ball 1 on the x axis: ending right of it means it went through.
bool orderFlipped(std::span<const BallState> b) {
  return b[0].position.x() > b[1].position.x();
}

// Any ball outside [lo, hi] went through a wall of the box.
std::function<bool(std::span<const BallState>)> outsideBox(Vec2 lo, Vec2 hi) {
  return [=](std::span<const BallState> balls) {
    for (const BallState& b : balls)
      if (b.position.x() < lo.x() || b.position.y() < lo.y() || b.position.x() > hi.x() ||
          b.position.y() > hi.y())
        return true;
    return false;
  };
}

std::uint64_t mix(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
double uniform(std::uint64_t& s) {
  return static_cast<double>(mix(s) >> 11) * 0x1.0p-53;
}

// Two balls head-on along x (1 m/s each way), meeting after 0.5 s.
StressCase headOn(const std::string& axis, const std::string& value, double m2, double r2,
                  double mu) {
  StressCase c{axis, value, {}, false, orderFlipped};
  c.scene.name = "stress: " + axis + " " + value;
  c.scene.contact = {1.0, mu};
  const double r1 = 0.5;
  c.scene.balls = {ball({0, 0}, r1, 1.0, {1, 0}, 2.0), ball({r1 + r2 + 1.0, 0}, r2, m2, {-1, 0})};
  c.scene.dt = 1e-3;
  c.scene.duration = 1.5;
  return c;
}

}  // namespace

Verdict classify(const StressObservation& o) {
  Verdict v;
  auto fail = [&](const std::string& why) {
    v.stable = false;
    v.reasons += (v.reasons.empty() ? "" : "; ") + why;
  };
  if (!o.finite) fail("non-finite");
  const double growth = (o.energyMax - o.energyStart) / o.energyScale;
  if (o.finite && !(growth <= kEnergyGrowth)) fail("energy +" + percent(growth));
  if (o.tunnelled) fail("tunnelled");
  if (o.atRest && !(o.overlapAtRest < kRestOverlap))
    fail("overlap " + percent(o.overlapAtRest) + " r");
  return v;
}

double sceneEnergy(const SceneDef& scene, std::span<const BallState> balls) {
  double e = 0.0;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const BallDef& d = scene.balls[i];
    const BallState& b = balls[i];
    e += 0.5 * d.mass * b.velocity.squaredNorm() +
         0.5 * d.resolvedInertia() * b.angularVelocity * b.angularVelocity -
         d.mass * scene.gravity.dot(b.position);
  }
  return e;
}

double maxRelativeOverlap(const SceneDef& scene, std::span<const BallState> balls) {
  double worst = 0.0;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const double ri = scene.balls[i].radius;
    for (std::size_t j = i + 1; j < balls.size(); ++j) {
      const double rj = scene.balls[j].radius;
      const double d = (balls[i].position - balls[j].position).norm();
      worst = std::max(worst, (ri + rj - d) / std::min(ri, rj));
    }
    for (const WallDef& w : scene.walls) {
      const Vec2 ab = w.b - w.a;
      const double len2 = ab.squaredNorm();
      const double t =
          len2 > 0 ? std::clamp((balls[i].position - w.a).dot(ab) / len2, 0.0, 1.0) : 0.0;
      const double d = (balls[i].position - (w.a + t * ab)).norm();
      worst = std::max(worst, (ri - d) / ri);
    }
  }
  return worst;
}

StressObservation observeStress(Stepper& s, const StressCase& c, long long every) {
  StressObservation o;
  std::vector<BallState> state(s.ballCount());
  auto read = [&] {
    for (std::size_t i = 0; i < state.size(); ++i) state[i] = s.ball(i);
    for (const BallState& b : state)
      if (!std::isfinite(b.position.x()) || !std::isfinite(b.position.y()) ||
          !std::isfinite(b.velocity.x()) || !std::isfinite(b.velocity.y()) ||
          !std::isfinite(b.angularVelocity))
        return false;
    return true;
  };
  read();
  o.energyStart = o.energyMax = sceneEnergy(c.scene, state);
  // The energy that can move around in the case: its kinetic energy plus the
  // potential energy of its height span (a pile falls through its own height).
  double kinetic = 0.0, lo = INFINITY, hi = -INFINITY, mass = 0.0;
  for (std::size_t i = 0; i < state.size(); ++i) {
    kinetic += 0.5 * c.scene.balls[i].mass * state[i].velocity.squaredNorm() +
               0.5 * c.scene.balls[i].resolvedInertia() * state[i].angularVelocity *
                   state[i].angularVelocity;
    const double h = -c.scene.gravity.dot(state[i].position);
    lo = std::min(lo, h);
    hi = std::max(hi, h);
    mass += c.scene.balls[i].mass;
  }
  o.energyScale = std::max(kinetic + mass * (hi - lo), 1e-300);
  const long long steps = c.scene.stepCount();
  for (long long k = 1; k <= steps; ++k) {
    s.step();
    if (k % every != 0 && k != steps) continue;
    if (!read()) {
      o.finite = false;
      return o;
    }
    o.energyMax = std::max(o.energyMax, sceneEnergy(c.scene, state));
  }
  o.tunnelled = c.tunnelled && c.tunnelled(state);
  o.atRest = c.endsAtRest;
  if (c.endsAtRest) o.overlapAtRest = std::max(0.0, maxRelativeOverlap(c.scene, state));
  for (std::size_t i = 0; i < state.size(); ++i)
    o.kineticAtEnd += 0.5 * c.scene.balls[i].mass * state[i].velocity.squaredNorm() +
                      0.5 * c.scene.balls[i].resolvedInertia() * state[i].angularVelocity *
                          state[i].angularVelocity;
  return o;
}

std::vector<StressCase> stressCases(bool longGas) {
  std::vector<StressCase> cases;
  // Mass ratio m2/m1 (spinning ball 1, mu = 0.3: the tangential impulse too).
  for (double q : {1e-6, 1e-3, 1.0, 1e3, 1e6})
    cases.push_back(headOn("mass ratio", num(q), q, 0.5, 0.3));
  // Radius ratio r2/r1 at equal mass.
  for (double q : {1e-3, 1e-2, 1e-1, 10.0, 1e2, 1e3})
    cases.push_back(headOn("radius ratio", num(q), 1.0, 0.5 * q, 0.3));
  // Speed in radii per step, against a wall and against another ball.
  for (double k : {0.1, 0.5, 1.0, 2.0, 5.0}) {
    StressCase w{"speed (wall)", num(k) + " r/step", {}, false, {}};
    const double r = 0.5, dt = 1e-3, v = k * r / dt;
    w.scene.name = "stress: ball at " + num(k) + " radii per step into a wall";
    w.scene.contact = {1.0, 0.0};
    WallDef wall;
    wall.a = {2, -5};
    wall.b = {2, 5};
    w.scene.walls = {wall};
    w.scene.balls = {ball({0, 0}, r, 1.0, {v, 0})};
    w.scene.dt = dt;
    w.scene.duration = std::max(0.05, 4.0 / v);
    w.tunnelled = [](std::span<const BallState> b) { return b[0].position.x() > 2.0; };
    cases.push_back(w);
    StressCase p = headOn("speed (ball)", num(k) + " r/step", 1.0, r, 0.0);
    p.scene.name = "stress: two balls closing at " + num(k) + " radii per step";
    p.scene.balls[0].velocity = {0.5 * v, 0};
    p.scene.balls[0].angularVelocity = 0.0;
    p.scene.balls[1].velocity = {-0.5 * v, 0};
    p.scene.duration = std::max(0.05, 4.0 / v);
    cases.push_back(p);
  }
  // Grazing impacts: the offset leaves 1 - delta of the contact distance.
  for (double delta : {1e-2, 1e-4, 1e-6, 1e-9}) {
    StressCase g = headOn("grazing", "1-" + num(delta), 1.0, 0.5, 0.3);
    g.scene.balls[1].position.y() = (1.0 - delta) * 1.0;
    g.tunnelled = {};
    cases.push_back(g);
  }
  // A long elastic gas: 200 smooth elastic balls in a box.
  {
    StressCase g{"elastic gas", longGas ? "1e6 steps" : "1e4 steps", {}, false, {}};
    g.scene.name = "stress: elastic gas of 200 balls";
    g.scene.contact = {1.0, 0.0};
    g.scene.walls = boxWalls({0, 0}, {10, 10});
    std::uint64_t seed = 3;
    for (int k = 0; k < 200; ++k) {
      const double a = 2 * std::numbers::pi * uniform(seed);
      g.scene.balls.push_back(ball({0.5 + 0.65 * (k % 14), 0.5 + 0.65 * (k / 14)}, 0.2, 1.0,
                                   {2 * std::cos(a), 2 * std::sin(a)}));
    }
    g.scene.dt = 1e-3;
    g.scene.duration = longGas ? 1000.0 : 10.0;
    g.tunnelled = outsideBox({0, 0}, {10, 10});
    cases.push_back(g);
  }
  // Dense piles settling under gravity: overlap and kinetic energy at rest.
  for (double e : {0.0, 0.5}) {
    StressCase p{"dense pile", "e = " + num(e), {}, true, {}};
    p.scene.name = "stress: pile of 200 balls settling, e = " + num(e);
    p.scene.gravity = {0, -9.81};
    p.scene.contact = {e, 0.5};
    p.scene.walls = boxWalls({0, 0}, {2, 8});
    std::uint64_t seed = 9;
    for (int k = 0; k < 200; ++k)
      p.scene.balls.push_back(
          ball({0.15 + 0.19 * (k % 10) + 0.01 * (uniform(seed) - 0.5), 0.15 + 0.21 * (k / 10)},
               0.09, 1.0));
    p.scene.dt = 1e-3;
    p.scene.duration = 4.0;
    p.tunnelled = outsideBox({0, 0}, {2, 8});
    cases.push_back(p);
  }
  // Scene scale: a ball bouncing in a box, every length (and gravity) times s.
  for (double s : {1e-4, 1e-2, 1.0, 1e2, 1e4}) {
    StressCase c{"scale", num(s), {}, false, {}};
    c.scene.name = "stress: bouncing ball at scale " + num(s);
    c.scene.gravity = {0, -9.81 * s};
    c.scene.contact = {0.9, 0.3};
    c.scene.walls = boxWalls({0, 0}, {4 * s, 4 * s});
    c.scene.balls = {ball({1 * s, 2 * s}, 0.5 * s, 1.0, {2 * s, 0}, 1.0),
                     ball({3 * s, 1 * s}, 0.4 * s, 1.0, {-1 * s, 1 * s})};
    c.scene.dt = 1e-3;
    c.scene.duration = 3.0;
    c.tunnelled = outsideBox({0, 0}, {4 * s, 4 * s});
    cases.push_back(c);
  }
  return cases;
}

}  // namespace particles::timestep
