// Box2D's limits, checked on a scene before it is run (box2d_range.h). The
// limits and where they come from are in box2d_limits.h; speeds and spins are
// estimated by box2d_peak.h.
#include "particles/reference/box2d_range.h"

#include <box2d/b2_contact.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <sstream>

#include "box2d_limits.h"
#include "box2d_material.h"
#include "box2d_peak.h"

namespace particles::reference {
namespace {

using namespace limits;

constexpr double kInf = std::numeric_limits<double>::infinity();

template <typename... Args>
std::string text(const Args&... args) {
  std::ostringstream out;
  out.precision(6);
  (out << ... << args);
  return out.str();
}

bool finiteFloat(double x) {
  return std::isfinite(x) && std::abs(x) <= FLT_MAX;
}
bool positiveNormalFloat(double x) {
  return finiteFloat(x) && x >= FLT_MIN;
}
bool finiteFloat(const Vec2& v) {
  return finiteFloat(v.x()) && finiteFloat(v.y());
}

void checkFloats(const SceneDef& scene, const Box2DSettings& settings,
                 std::vector<RangeIssue>& out) {
  auto issue = [&](int index, const std::string& what) {
    out.push_back({RangeCode::FloatRange, index, what + " is not representable as a float"});
  };
  if (!positiveNormalFloat(settings.dt)) issue(-1, text("dt = ", settings.dt));
  if (!finiteFloat(scene.gravity)) issue(-1, "gravity");
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    const BallDef& b = scene.balls[i];
    const bool ok = finiteFloat(b.position) && finiteFloat(b.velocity) && finiteFloat(b.angle) &&
                    finiteFloat(b.angularVelocity) && positiveNormalFloat(b.radius) &&
                    positiveNormalFloat(b.mass) && positiveNormalFloat(b.resolvedInertia());
    if (!ok) issue(static_cast<int>(i), text("a value of ball ", i));
  }
  for (std::size_t k = 0; k < scene.walls.size(); ++k)
    if (!finiteFloat(scene.walls[k].a) || !finiteFloat(scene.walls[k].b))
      issue(static_cast<int>(k), text("a vertex of wall ", k));
  for (std::size_t k = 0; k < scene.forces.size(); ++k) {
    const ForceDef& f = scene.forces[k];
    if (!finiteFloat(f.target) || !finiteFloat(f.stiffness) || !finiteFloat(f.force) ||
        !finiteFloat(f.torque))
      issue(static_cast<int>(k), text("a value of force ", k));
  }
}

void checkMotion(const SceneDef& scene, const Box2DSettings& settings,
                 std::vector<RangeIssue>& out) {
  const std::size_t n = scene.balls.size();
  std::vector<Peak> peak(n);
  std::size_t fastest = 0;
  double second = 0.0;  // m/s, the fastest speed but one
  for (std::size_t i = 0; i < n; ++i) {
    peak[i] = estimatePeak(scene, i);
    if (i == 0) continue;
    if (peak[i].speed > peak[fastest].speed) {
      second = peak[fastest].speed;
      fastest = i;
    } else {
      second = std::max(second, peak[i].speed);
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double move = peak[i].speed * settings.dt;
    if (move > kMaxTranslation)
      out.push_back({RangeCode::MaxTranslation, static_cast<int>(i),
                     text("ball ", i, " may move ", move, " m in one step (speed up to ",
                          peak[i].speed, " m/s); b2_maxTranslation = ", kMaxTranslation, " m")});
  }
  for (std::size_t i = 0; i < n; ++i) {
    const BallDef& b = scene.balls[i];
    // Friction can spin a ball up by at most (slip speed) / r in a contact
    // (the tangential impulse at most cancels the slip, and the ball's share
    // of it turns into r dw <= slip). The slip is bounded by the ball's own
    // speed plus the fastest other ball's (a wall stands still).
    const double partner = i == fastest ? second : peak[fastest].speed;
    const bool grips = resolveMaterial(scene.contact, b.restitution, b.friction).friction > 0.0;
    const double spin = peak[i].spin + (grips ? (peak[i].speed + partner) / b.radius : 0.0);
    const double turn = spin * settings.dt;
    if (turn > kMaxRotation)
      out.push_back({RangeCode::MaxRotation, static_cast<int>(i),
                     text("ball ", i, " may turn ", turn, " rad in one step (spin up to ", spin,
                          " rad/s); b2_maxRotation = ", kMaxRotation, " rad")});
  }
}

void checkSizes(const SceneDef& scene, std::vector<RangeIssue>& out) {
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    const double r = scene.balls[i].radius;
    if (r < kMinRadius || r > kMaxRadius)
      out.push_back({RangeCode::RadiusRange, static_cast<int>(i),
                     text("ball ", i, " has radius ", r, " m; Box2D is tuned for ", kMinRadius, "-",
                          kMaxRadius, " m")});
  }
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    const double r = scene.balls[i].radius;
    if (r < kMinSlopsPerRadius * kLinearSlop)
      out.push_back({RangeCode::LinearSlop, static_cast<int>(i),
                     text("ball ", i, " has radius ", r, " m, under ", kMinSlopsPerRadius,
                          " x b2_linearSlop (", kLinearSlop, " m), the overlap Box2D tolerates")});
  }
  for (std::size_t k = 0; k < scene.walls.size(); ++k) {
    const double length = (scene.walls[k].b - scene.walls[k].a).norm();
    if (length > kMaxWallLength)
      out.push_back(
          {RangeCode::WallLength, static_cast<int>(k),
           text("wall ", k, " is ", length, " m long; Box2D is tuned for static shapes up to ",
                kMaxWallLength, " m")});
  }
}

// Spacing of floats at the largest coordinate the scene starts with (balls and
// wall vertices), or that a ball could reach in free flight without walls.
void checkPrecision(const SceneDef& scene, std::vector<RangeIssue>& out) {
  if (scene.balls.empty()) return;
  double extent = 0.0, smallest = kInf;
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    const BallDef& b = scene.balls[i];
    const double reach = scene.walls.empty() ? estimatePeak(scene, i).speed * scene.duration : 0.0;
    extent = std::max(extent, b.position.cwiseAbs().maxCoeff() + b.radius + reach);
    smallest = std::min(smallest, b.radius);
  }
  for (const WallDef& w : scene.walls)
    extent = std::max({extent, w.a.cwiseAbs().maxCoeff(), w.b.cwiseAbs().maxCoeff()});
  const float f = static_cast<float>(std::min(extent, static_cast<double>(FLT_MAX)));
  const double spacing = std::nextafter(f, std::numeric_limits<float>::infinity()) - f;
  if (spacing > kPositionResolution * smallest)
    out.push_back(
        {RangeCode::PositionPrecision, -1,
         text("coordinates up to ", extent, " m have a float spacing of ", spacing, " m, over ",
              kPositionResolution, " of the smallest radius (", smallest, " m)")});
}

void checkMasses(const SceneDef& scene, std::vector<RangeIssue>& out) {
  if (scene.balls.size() < 2) return;
  double lo = kInf, hi = 0.0;
  for (const BallDef& b : scene.balls) {
    lo = std::min(lo, b.mass);
    hi = std::max(hi, b.mass);
  }
  if (hi > kMaxMassRatio * lo)
    out.push_back(
        {RangeCode::MassRatio, -1,
         text("ball masses range from ", lo, " to ", hi, " kg, a ratio over ", kMaxMassRatio)});
}

// The smallest mixed friction Box2D would give a contact that the engine
// treats as no-slip (infinite); infinity when there is no such contact. Such a
// contact needs a no-slip side and a side with mu > 0 (mixed with 0 both give
// 0), and walls never meet walls, so only the smallest finite mu of the balls
// and of the walls matters.
double weakestNoSlip(const SceneDef& scene, const Box2DSettings& settings) {
  struct Side {
    int noSlip = 0;         // bodies with mu = kNoSlip
    double weakest = kInf;  // smallest finite mu > 0
  };
  auto add = [](Side& side, double mu) {
    if (std::isinf(mu))
      ++side.noSlip;
    else if (mu > 0.0)
      side.weakest = std::min(side.weakest, mu);
  };
  Side balls, walls;
  for (const BallDef& b : scene.balls)
    add(balls, resolveMaterial(scene.contact, b.restitution, b.friction).friction);
  for (const WallDef& w : scene.walls)
    add(walls, resolveMaterial(scene.contact, w.restitution, w.friction).friction);

  auto box2d = [&](double mu) { return toBox2DMaterial({1.0, mu}, settings).friction; };
  double weakest = kInf;
  auto mix = [&](double mu1, double mu2) {
    weakest = std::min(weakest, static_cast<double>(b2MixFriction(box2d(mu1), box2d(mu2))));
  };
  if (balls.noSlip > 0) {
    if (balls.weakest < kInf) mix(kNoSlip, balls.weakest);
    if (walls.weakest < kInf) mix(kNoSlip, walls.weakest);
    if (balls.noSlip > 1 || walls.noSlip > 0) mix(kNoSlip, kNoSlip);
  }
  if (walls.noSlip > 0 && balls.weakest < kInf) mix(balls.weakest, kNoSlip);
  return weakest;
}

void checkSolver(const SceneDef& scene, const Box2DSettings& settings,
                 std::vector<RangeIssue>& out) {
  const double weakest = weakestNoSlip(scene, settings);
  if (weakest < kEffectivelyNoSlip)
    out.push_back({RangeCode::NoSlipMixing, -1,
                   text("a no-slip contact mixes to mu = ", weakest,
                        " in Box2D (noSlipFriction = ", settings.noSlipFriction, "), under ",
                        kEffectivelyNoSlip, ": its friction may clamp")});
  // b2ContactSolver::SolveVelocityConstraints solves the tangent constraint
  // first, clamped to mu * normalImpulse; a new contact's normal impulse is
  // still 0 in the first iteration.
  if (settings.velocityIterations < 2)
    out.push_back({RangeCode::VelocityIterations, -1,
                   text("velocityIterations = ", settings.velocityIterations,
                        ": friction of a new contact sees no normal impulse (needs >= 2)")});
  if (settings.positionIterations < 1)
    out.push_back({RangeCode::PositionIterations, -1,
                   text("positionIterations = ", settings.positionIterations,
                        ": overlaps are never corrected")});
}

}  // namespace

std::vector<RangeIssue> checkBox2DRange(const SceneDef& scene, const Box2DSettings& settings) {
  std::vector<RangeIssue> out;
  checkFloats(scene, settings, out);
  checkMotion(scene, settings, out);
  checkSizes(scene, out);
  checkPrecision(scene, out);
  checkMasses(scene, out);
  checkSolver(scene, settings, out);
  return out;
}

const char* rangeCodeName(RangeCode code) {
  switch (code) {
    case RangeCode::FloatRange:
      return "FloatRange";
    case RangeCode::MaxTranslation:
      return "MaxTranslation";
    case RangeCode::MaxRotation:
      return "MaxRotation";
    case RangeCode::RadiusRange:
      return "RadiusRange";
    case RangeCode::LinearSlop:
      return "LinearSlop";
    case RangeCode::WallLength:
      return "WallLength";
    case RangeCode::PositionPrecision:
      return "PositionPrecision";
    case RangeCode::MassRatio:
      return "MassRatio";
    case RangeCode::NoSlipMixing:
      return "NoSlipMixing";
    case RangeCode::VelocityIterations:
      return "VelocityIterations";
    case RangeCode::PositionIterations:
      return "PositionIterations";
  }
  return "?";
}

}  // namespace particles::reference
