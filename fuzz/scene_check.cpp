#include "scene_check.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "particles/scenefile.h"
#include "particles/world.h"

namespace particles::fuzz {
namespace {

// The physical range: every magnitude 0 or within [1e-6, 1e6] in SI units.
// Inside it, kMaxSteps steps cannot overflow a double (the worst growth per
// step, a pull spring's k dt^2 / m, is 1e24), so a non-finite state there is
// a solver bug; outside it, overflow is legitimate and the CLI reports it as
// divergence.
bool physical(double x) {
  const double a = std::abs(x);
  return a == 0.0 || (a >= 1e-6 && a <= 1e6);
}

bool physical(const Vec2& v) {
  return physical(v.x()) && physical(v.y());
}

bool physical(const SceneDef& s) {
  bool ok = physical(s.gravity) && physical(s.dt);
  for (const BallDef& b : s.balls)
    ok = ok && physical(b.position) && physical(b.velocity) && physical(b.angularVelocity) &&
         physical(b.radius) && physical(b.mass) && physical(b.resolvedInertia());
  for (const WallDef& w : s.walls) ok = ok && physical(w.a) && physical(w.b);
  for (const ForceDef& f : s.forces)
    ok = ok && physical(f.target) && physical(f.stiffness) && physical(f.force) &&
         physical(f.torque);
  return ok;
}

// "fuzz.json: not valid JSON: ..." or "fuzz.json: PATH: PROBLEM" with a
// non-empty PATH ("top level" for the document itself) and PROBLEM, on one
// line. A document that is valid JSON must not be called invalid JSON.
std::string messageViolation(const std::string& message, std::string_view text) {
  const std::string prefix = std::string(kFileName) + ": ";
  if (!message.starts_with(prefix)) return "message does not start with the file name: " + message;
  if (message.find('\n') != std::string::npos) return "message is not one line: " + message;
  const std::string rest = message.substr(prefix.size());
  if (rest.starts_with("not valid JSON: ")) {
    if (nlohmann::json::accept(text)) return "valid JSON rejected as invalid JSON: " + message;
    return "";
  }
  const std::size_t colon = rest.find(": ");
  if (colon == 0 || colon == std::string::npos || colon + 2 >= rest.size())
    return "message names no JSON path: " + message;
  return "";
}

bool finite(const World& w) {
  for (std::size_t i = 0; i < w.ballCount(); ++i) {
    const BallState b = w.ball(i);
    if (!b.position.allFinite() || !b.velocity.allFinite() || !std::isfinite(b.angle) ||
        !std::isfinite(b.angularVelocity))
      return false;
  }
  return true;
}

}  // namespace

Check checkSceneInput(std::string_view text) {
  Check c;
  SceneDef scene;
  try {
    scene = parseScene(text, std::string(kFileName));
  } catch (const SceneError& e) {
    c.violation = messageViolation(e.what(), text);
    return c;
  }
  if (scene.balls.size() > kMaxBalls || scene.walls.size() > kMaxWalls) {
    c.outcome = Outcome::TooBig;
    return c;
  }
  scene.solver.contactPasses = std::min(scene.solver.contactPasses, kMaxPasses);
  scene.solver.correctionPasses = std::min(scene.solver.correctionPasses, kMaxPasses);
  World world(scene);
  if (!finite(world)) {
    c.violation = "the loader accepted a scene whose initial state is not finite";
    return c;
  }
  // Like `particles run`, stop at the first non-finite state: stepping NaNs
  // on only costs time (it once made an input exceed the -timeout).
  const long long steps = std::min(scene.stepCount(), kMaxSteps);
  long long k = 0;
  while (k < steps && finite(world)) {
    world.step();
    ++k;
  }
  if (finite(world)) {
    c.outcome = Outcome::Finite;
  } else {
    c.outcome = Outcome::Diverged;
    if (physical(scene))
      c.violation = "non-finite state after " + std::to_string(k) +
                    " steps of a scene inside the physical range";
  }
  return c;
}

const char* outcomeName(Outcome o) {
  switch (o) {
    case Outcome::Rejected:
      return "rejected";
    case Outcome::TooBig:
      return "too big to step";
    case Outcome::Finite:
      return "finite";
    case Outcome::Diverged:
      return "diverged (outside the physical range)";
  }
  return "?";
}

}  // namespace particles::fuzz
