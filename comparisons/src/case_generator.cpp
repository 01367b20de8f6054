#include "particles/compare/case_generator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "case_random.h"

namespace particles::compare {
namespace {

using detail::CaseRandom;

BallDef makeBall(const Vec2& x, const Vec2& v, double w, double r, double m) {
  BallDef b;
  b.position = x;
  b.velocity = v;
  b.angularVelocity = w;
  b.radius = r;
  b.mass = m;
  return b;
}

SceneDef emptyScene(const std::string& name, double e, double mu, double dt) {
  SceneDef s;
  s.name = name;
  s.contact = {e, mu};
  s.dt = dt;
  s.duration = dt;
  return s;
}

// The friction coefficient at which a contact is exactly at the edge of
// sticking: the no-slip impulse M_t |g_t| equals mu (1 + e) M_n |g_n|
// (docs/physics.md; PHYSICS-REFERENCES.md with beta0 = 0).
double stickingThreshold(const BallDef& a, const BallDef* b, const Vec2& n, double e) {
  const Vec2 tau = perpLeft(n);
  const double ia = 1.0 / a.mass, ja = a.radius * a.radius / a.resolvedInertia();
  const double ib = b ? 1.0 / b->mass : 0.0;
  const double jb = b ? b->radius * b->radius / b->resolvedInertia() : 0.0;
  const Vec2 vb = b ? b->velocity : Vec2::Zero();
  const double wb = b ? b->angularVelocity * b->radius : 0.0;
  const double gn = (vb - a.velocity).dot(n);
  const double gt = (vb - a.velocity).dot(tau) - wb - a.angularVelocity * a.radius;
  const double mn = 1.0 / (ia + ib), mt = 1.0 / (ia + ib + ja + jb);
  return mt * std::abs(gt) / ((1.0 + e) * mn * std::abs(gn));
}

double drawRestitution(CaseRandom& rng) {
  const double u = rng.uniform();
  if (u < 0.1) return 0.0;  // the ends of [0, 1] are where sign errors hide
  if (u < 0.2) return 1.0;
  return rng.uniform();
}

// Inertia: half the cases a uniform disk, the rest J = q m r^2 with q from a
// thin-ring-like 1 down to a centre-heavy 0.1.
void drawInertia(CaseRandom& rng, BallDef& b) {
  if (rng.uniform() < 0.5) b.inertia = rng.uniform(0.1, 1.0) * b.mass * b.radius * b.radius;
}

// Spins up to twice the rolling rate s / r, capped so that one step turns a
// ball by less than Box2D's b2_maxRotation (pi / 2).
double drawSpin(CaseRandom& rng, double speed, double r, double dt) {
  const double cap = 0.25 * std::numbers::pi / dt;
  return rng.uniform(-1.0, 1.0) * std::min(2.0 * speed / r, cap);
}

ImpactCase ballBall(Family family, CaseRandom& rng, const GeneratorSettings& g,
                    const std::string& name) {
  CaseParams p;
  p.massRatio = rng.logUniform(g.minMassRatio, g.maxMassRatio);
  p.radiusRatio = rng.logUniform(g.minRadiusRatio, g.maxRadiusRatio);
  p.speed = rng.logUniform(g.minSpeed, g.maxSpeed);
  p.impactAngle = rng.uniform(0.0, g.maxImpactAngle);
  p.restitution = drawRestitution(rng);
  // Sizes and masses balanced around 1 so both bodies stay in Box2D's range.
  const double size = rng.uniform(0.35, 1.0);
  const double ra = size / std::sqrt(p.radiusRatio), rb = size * std::sqrt(p.radiusRatio);
  const double ma = 1.0 / std::sqrt(p.massRatio), mb = std::sqrt(p.massRatio);

  const double theta = rng.uniform(0.0, 2.0 * std::numbers::pi);
  const Vec2 n(std::cos(theta), std::sin(theta)), tau = perpLeft(n);
  const Vec2 dv =
      p.speed * (-std::cos(p.impactAngle) * n + rng.sign() * std::sin(p.impactAngle) * tau);
  const Vec2 drift = p.speed * Vec2(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
  const double overlap = kPlacementOverlap * (ra + rb);

  BallDef a = makeBall(-(ra - 0.5 * overlap) * n, drift - mb / (ma + mb) * dv,
                       drawSpin(rng, p.speed, ra, g.dt), ra, ma);
  BallDef b = makeBall((rb - 0.5 * overlap) * n, drift + ma / (ma + mb) * dv,
                       drawSpin(rng, p.speed, rb, g.dt), rb, mb);
  drawInertia(rng, a);
  drawInertia(rng, b);

  switch (family) {
    case Family::NoSlip:
      p.friction = kNoSlip;
      break;
    case Family::Smooth:
      p.friction = 0.0;
      break;
    case Family::FrictionSliding:
      p.friction = stickingThreshold(a, &b, n, p.restitution) * rng.uniform(0.05, 0.8);
      break;
    default:
      p.friction = stickingThreshold(a, &b, n, p.restitution) * rng.uniform(1.25, 4.0);
      break;
  }
  ImpactCase c{name, family, emptyScene(name, p.restitution, p.friction, g.dt), p, true};
  c.scene.balls = {a, b};
  return c;
}

ImpactCase ballWall(CaseRandom& rng, const GeneratorSettings& g, const std::string& name) {
  CaseParams p;
  p.massRatio = 0.0;
  p.radiusRatio = 0.0;
  p.speed = rng.logUniform(g.minSpeed, g.maxSpeed);
  p.impactAngle = rng.uniform(0.0, g.maxImpactAngle);
  p.restitution = drawRestitution(rng);
  const double r = rng.uniform(0.2, 2.0);
  const double m = rng.logUniform(0.1, 10.0);

  // n points from the ball to the wall; the wall passes through the contact
  // point (the origin) along tau.
  const double theta = rng.uniform(0.0, 2.0 * std::numbers::pi);
  const Vec2 n(std::cos(theta), std::sin(theta)), tau = perpLeft(n);
  const Vec2 v =
      p.speed * (std::cos(p.impactAngle) * n + rng.sign() * std::sin(p.impactAngle) * tau);
  BallDef a =
      makeBall(-(1.0 - kPlacementOverlap) * r * n, v, drawSpin(rng, p.speed, r, g.dt), r, m);
  drawInertia(rng, a);

  const double threshold = stickingThreshold(a, nullptr, n, p.restitution);
  switch (rng.below(4)) {
    case 0:
      p.friction = kNoSlip;
      break;
    case 1:
      p.friction = 0.0;
      break;
    case 2:
      p.friction = threshold * rng.uniform(0.05, 0.8);
      break;
    default:
      p.friction = threshold * rng.uniform(1.25, 4.0);
      break;
  }
  ImpactCase c{name, Family::Wall, emptyScene(name, p.restitution, p.friction, g.dt), p, true};
  c.scene.balls = {a};
  WallDef w;
  w.a = -10.0 * r * tau;
  w.b = 10.0 * r * tau;
  c.scene.walls = {w};
  return c;
}

// Equal balls in a row along +x, touching, the first one moving into them.
ImpactCase cradle(int count, double speed, double e, double mu, double r, double dt,
                  const std::string& name) {
  ImpactCase c{name, Family::MultiContact, emptyScene(name, e, mu, dt), {}, false};
  c.params = {1.0, 1.0, e, mu, 0.0, speed};
  const double step = 2.0 * r * (1.0 - kPlacementOverlap);
  for (int i = 0; i < count; ++i)
    c.scene.balls.push_back(
        makeBall(Vec2(i * step, 0.0), Vec2(i == 0 ? speed : 0.0, 0.0), 0.0, r, 1.0));
  return c;
}

// A ball moving into two balls that touch it at +-alpha from its velocity,
// like the cue ball of a break.
ImpactCase threeBalls(double alpha, double speed, double e, double mu, double spin, double dt,
                      const std::string& name) {
  ImpactCase c{name, Family::MultiContact, emptyScene(name, e, mu, dt), {}, false};
  c.params = {1.0, 1.0, e, mu, alpha, speed};
  const double r = 0.5, d = 2.0 * r * (1.0 - kPlacementOverlap);
  c.scene.balls = {
      makeBall(Vec2::Zero(), Vec2(speed, 0.0), spin, r, 1.0),
      makeBall(d * Vec2(std::cos(alpha), std::sin(alpha)), Vec2::Zero(), 0.0, r, 1.0),
      makeBall(d * Vec2(std::cos(alpha), -std::sin(alpha)), Vec2::Zero(), 0.0, r, 1.0)};
  return c;
}

// A ball touching a floor and a wall at once, in a frame turned by `frame`,
// moving into the corner.
ImpactCase corner(double frame, double speed, double angle, double e, double mu, double spin,
                  double dt, const std::string& name) {
  ImpactCase c{name, Family::MultiContact, emptyScene(name, e, mu, dt), {}, false};
  c.params = {0.0, 0.0, e, mu, angle, speed};
  const double r = 0.5, inset = r * (1.0 - kPlacementOverlap);
  const Vec2 ex(std::cos(frame), std::sin(frame)), ey = perpLeft(ex);
  const Vec2 centre = inset * (ex + ey);
  const Vec2 v = -speed * (std::cos(angle) * ex + std::sin(angle) * ey);
  c.scene.balls = {makeBall(centre, v, spin, r, 1.0)};
  WallDef floor, wall;
  floor.a = Vec2::Zero();
  floor.b = 10.0 * ex;
  wall.a = Vec2::Zero();
  wall.b = 10.0 * ey;
  c.scene.walls = {floor, wall};
  return c;
}

ImpactCase multiContact(CaseRandom& rng, const GeneratorSettings& g, const std::string& name) {
  const double speed = rng.logUniform(g.minSpeed, g.maxSpeed);
  const double e = drawRestitution(rng);
  const double mu = rng.uniform() < 0.3 ? 0.0 : rng.logUniform(0.05, 2.0);
  switch (rng.below(3)) {
    case 0:
      return cradle(3 + rng.below(3), speed, e, mu, rng.uniform(0.2, 1.0), g.dt, name);
    case 1:
      return threeBalls(rng.uniform(0.35, 1.05), speed, e, mu, drawSpin(rng, speed, 0.5, g.dt),
                        g.dt, name);
    default:
      return corner(rng.uniform(0.0, 2.0 * std::numbers::pi), speed, rng.uniform(0.1, 1.47), e, mu,
                    drawSpin(rng, speed, 0.5, g.dt), g.dt, name);
  }
}

// Two equal balls meeting head-on along x at `speed` each, with given spins.
ImpactCase headOn(const std::string& name, Family family, double w1, double w2, double e,
                  double mu) {
  const double r = 0.5, dt = 1.0 / 60.0, overlap = kPlacementOverlap * 2.0 * r;
  ImpactCase c{name, family, emptyScene(name, e, mu, dt), {1.0, 1.0, e, mu, 0.0, 4.0}, true};
  c.scene.balls = {makeBall(Vec2(-(r - 0.5 * overlap), 0.0), Vec2(2.0, 0.0), w1, r, 1.0),
                   makeBall(Vec2(r - 0.5 * overlap, 0.0), Vec2(-2.0, 0.0), w2, r, 1.0)};
  return c;
}

// A ball hitting the floor y = 0 obliquely with a spin.
ImpactCase floorHit(const std::string& name, double vx, double vy, double w, double e, double mu) {
  const double r = 0.5, dt = 1.0 / 60.0;
  ImpactCase c{name, Family::Wall, emptyScene(name, e, mu, dt), {}, true};
  c.params = {0.0, 0.0, e, mu, std::atan2(std::abs(vx), std::abs(vy)), std::hypot(vx, vy)};
  c.scene.balls = {makeBall(Vec2(0.0, r * (1.0 - kPlacementOverlap)), Vec2(vx, vy), w, r, 1.0)};
  WallDef floor;
  floor.a = Vec2(-10.0, 0.0);
  floor.b = Vec2(10.0, 0.0);
  c.scene.walls = {floor};
  return c;
}

}  // namespace

ImpactCase randomCase(Family family, std::uint64_t seed, int index,
                      const GeneratorSettings& settings) {
  CaseRandom rng(seed, static_cast<std::uint64_t>(family) + 1, static_cast<std::uint64_t>(index));
  const std::string name =
      "random/" + std::string(familyName(family)) + "/" + std::to_string(index);
  switch (family) {
    case Family::Wall:
      return ballWall(rng, settings, name);
    case Family::MultiContact:
      return multiContact(rng, settings, name);
    default:
      return ballBall(family, rng, settings, name);
  }
}

std::vector<ImpactCase> catalogue() {
  const double dt = 1.0 / 60.0;
  std::vector<ImpactCase> cases;
  // The handout's thought experiments: same spins exchange tangential
  // impulse, opposite spins (surfaces moving together, like gears) do not.
  cases.push_back(headOn("catalogue/head-on, same spins", Family::NoSlip, 5.0, 5.0, 0.5, kNoSlip));
  cases.push_back(
      headOn("catalogue/head-on, opposite spins (gears)", Family::NoSlip, 5.0, -5.0, 0.5, kNoSlip));
  cases.push_back(headOn("catalogue/head-on, same spins, friction-limited", Family::FrictionSliding,
                         5.0, 5.0, 0.5, 0.1));
  cases.push_back(headOn("catalogue/head-on, elastic, smooth", Family::Smooth, 0.0, 0.0, 1.0, 0.0));
  cases.push_back(
      headOn("catalogue/head-on, perfectly inelastic", Family::Smooth, 0.0, 0.0, 0.0, 0.0));
  cases.push_back(floorHit("catalogue/floor, oblique, no-slip", 2.0, -3.0, 0.0, 0.5, kNoSlip));
  cases.push_back(floorHit("catalogue/floor, oblique, sliding", 2.0, -3.0, 0.0, 0.5, 0.1));
  cases.push_back(floorHit("catalogue/floor, oblique, sticking", 2.0, -3.0, 0.0, 0.5, 1.0));
  cases.push_back(floorHit("catalogue/floor, backspin, no-slip", 1.0, -1.0, 8.0, 0.3, kNoSlip));
  cases.push_back(
      floorHit("catalogue/floor, vertical drop, spinning, sliding", 0.0, -2.0, 10.0, 0.8, 0.2));
  cases.push_back(cradle(3, 2.0, 1.0, 0.0, 0.5, dt, "catalogue/Newton's cradle, 3 balls"));
  cases.push_back(cradle(5, 2.0, 1.0, 0.0, 0.5, dt, "catalogue/Newton's cradle, 5 balls"));
  cases.push_back(threeBalls(std::numbers::pi / 6.0, 3.0, 0.9, 0.2, 0.0, dt,
                             "catalogue/break: one ball into two"));
  cases.push_back(corner(0.0, 2.0, std::numbers::pi / 4.0, 1.0, 0.0, 0.0, dt,
                         "catalogue/ball into a corner, elastic, smooth"));
  cases.push_back(corner(0.3, 2.0, 0.6, 0.5, kNoSlip, 3.0, dt,
                         "catalogue/ball into a corner, no-slip, spinning"));
  return cases;
}

}  // namespace particles::compare
