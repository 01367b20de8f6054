#include "particles/viewer/readout.h"

#include <algorithm>
#include <cstdio>

namespace particles::viewer {
namespace {

std::string format(const char* pattern, auto... values) {
  char buf[256];
  std::snprintf(buf, sizeof buf, pattern, values...);
  return buf;
}

std::string energyLine(const char* name, const EnergyReadout& e) {
  return format("%-7s KE %.5g J  rot %.5g J  PE %.5g J  total %.6g J  p (%.4g, %.4g) kg m/s", name,
                e.translational, e.rotational, e.potential, e.total(), e.momentum.x(),
                e.momentum.y());
}

}  // namespace

EnergyReadout measureEnergy(const SceneDef& scene, const std::vector<BallState>& balls) {
  EnergyReadout e;
  const std::size_t n = std::min(balls.size(), scene.balls.size());
  for (std::size_t i = 0; i < n; ++i) {
    const BallDef& def = scene.balls[i];
    const BallState& b = balls[i];
    e.translational += 0.5 * def.mass * b.velocity.squaredNorm();
    e.rotational += 0.5 * def.resolvedInertia() * b.angularVelocity * b.angularVelocity;
    e.potential -= def.mass * scene.gravity.dot(b.position);
    e.momentum += def.mass * b.velocity;
  }
  return e;
}

Discrepancy largestDifference(const std::vector<BallState>& engine,
                              const std::vector<BallState>& box2d) {
  Discrepancy d;
  const std::size_t n = std::min(engine.size(), box2d.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = (engine[i].position - box2d[i].position).norm();
    const double dv = (engine[i].velocity - box2d[i].velocity).norm();
    if (d.positionBall < 0 || dx > d.position) {
      d.position = dx;
      d.positionBall = static_cast<int>(i);
    }
    if (d.velocityBall < 0 || dv > d.velocity) {
      d.velocity = dv;
      d.velocityBall = static_cast<int>(i);
    }
  }
  return d;
}

std::vector<std::string> readoutLines(const Session& session, ViewMode mode) {
  const World& world = session.engine();
  std::vector<std::string> lines;
  lines.push_back(format("t = %.3f s  step %lld  dt %g s  x%g%s  mode %s", world.time(),
                         world.stepIndex(), world.dt(), session.timeScale(),
                         session.paused() ? "  PAUSED" : "", std::string(modeName(mode)).c_str()));
  const std::vector<BallState> engine = session.engineBalls();
  lines.push_back(energyLine("engine", measureEnergy(session.scene(), engine)));
  if (session.hasBox2D()) {
    const std::vector<BallState> box2d = session.box2dBalls();
    lines.push_back(energyLine("Box2D", measureEnergy(session.scene(), box2d)));
    const Discrepancy d = largestDifference(engine, box2d);
    lines.push_back(format("max |dx| %.3g m (ball %d)  max |dv| %.3g m/s (ball %d)", d.position,
                           d.positionBall, d.velocity, d.velocityBall));
  } else {
    lines.push_back("Box2D: unavailable (" + session.box2dError() + ")");
  }
  if (const std::optional<int> held = session.held()) {
    const BallState b = world.ball(static_cast<std::size_t>(*held));
    const double k = session.pullStiffness(*held);
    lines.push_back(format("pull on ball %d: k = %.4g N/m, |F| = k |M - O| = %.4g N", *held, k,
                           k * (session.holdTarget() - b.position).norm()));
  }
  return lines;
}

std::string keyHelpLine(bool withMouse) {
  const std::string keys =
      "M mode  P pause  O step  R restart  D contacts  +/- speed  H text  F12 png  Esc quit";
  return withMouse ? keys + "  mouse: left pull, right pan, wheel zoom" : keys;
}

}  // namespace particles::viewer
