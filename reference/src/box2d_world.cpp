// Building and stepping the Box2D twin. The mapping of each scene item is
// explained in docs/box2d-twin.md; the comments here say why each Box2D knob
// is set the way it is.
#include <cmath>
#include <stdexcept>
#include <string>

#include "box2d_limits.h"
#include "box2d_material.h"
#include "box2d_world_impl.h"

namespace particles::reference {
namespace {

// Rejects what Box2D cannot represent at all, before anything is destroyed, so
// a failed reset() leaves the previous world intact.
void validate(const SceneDef& scene, const Box2DSettings& settings) {
  if (!(settings.dt > 0.0)) throw std::invalid_argument("Box2DWorld: settings.dt must be > 0");
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    const BallDef& b = scene.balls[i];
    // b2Body::SetMassData silently replaces a mass <= 0 by 1 kg and ignores
    // an inertia <= 0; a radius <= 0 is no circle.
    if (!(b.mass > 0.0) || !(b.resolvedInertia() > 0.0) || !(b.radius > 0.0))
      throw std::invalid_argument("Box2DWorld: ball " + std::to_string(i) +
                                  " needs mass, inertia and radius > 0");
  }
  for (std::size_t k = 0; k < scene.forces.size(); ++k) {
    const int ball = scene.forces[k].ball;
    if (ball < 0 || static_cast<std::size_t>(ball) >= scene.balls.size())
      throw std::invalid_argument("Box2DWorld: force " + std::to_string(k) +
                                  " acts on a missing ball");
  }
}

void setMaterial(b2FixtureDef& def, const ContactMaterial& material,
                 const Box2DSettings& settings) {
  const FixtureMaterial m = toBox2DMaterial(material, settings);
  def.friction = m.friction;
  def.restitution = m.restitution;
  def.restitutionThreshold = m.restitutionThreshold;
}

b2Body* addBall(b2World& world, const SceneDef& scene, std::size_t index,
                const Box2DSettings& settings) {
  const BallDef& ball = scene.balls[index];
  b2BodyDef def;
  def.type = b2_dynamicBody;
  def.position = toB2(ball.position);
  def.angle = static_cast<float>(ball.angle);
  def.linearVelocity = toB2(ball.velocity);
  def.angularVelocity = static_cast<float>(ball.angularVelocity);
  // The engine has no damping, no sleeping and no continuous collision
  // between moving balls; b2BodyDef's defaults already say so for damping,
  // fixed rotation and bullets, sleeping is switched off here and world-wide.
  def.allowSleep = false;
  def.bullet = false;
  def.fixedRotation = false;
  def.linearDamping = 0.0f;
  def.angularDamping = 0.0f;
  b2Body* body = world.CreateBody(&def);

  b2CircleShape circle;  // centred on the body origin: m_p = (0, 0)
  circle.m_radius = static_cast<float>(ball.radius);
  b2FixtureDef fixture;
  fixture.shape = &circle;
  // Density 0: CreateFixture then computes no mass of its own; the mass and
  // inertia are set exactly below, whatever a density would round to.
  fixture.density = 0.0f;
  setMaterial(fixture, resolveMaterial(scene.contact, ball.restitution, ball.friction), settings);
  fixture.userData.pointer = index;
  body->CreateFixture(&fixture);

  // b2MassData::I is the inertia about the body origin; with the centre of
  // mass at the origin that is the inertia about the centre, as in the scene.
  b2MassData mass;
  mass.mass = static_cast<float>(ball.mass);
  mass.center.SetZero();
  mass.I = static_cast<float>(ball.resolvedInertia());
  body->SetMassData(&mass);
  return body;
}

// All walls on one static body at the origin, so edge vertices are world
// coordinates. Two static fixtures never form a contact.
void addWalls(b2World& world, const SceneDef& scene, const Box2DSettings& settings,
              std::vector<b2Fixture*>& out) {
  if (scene.walls.empty()) return;
  b2BodyDef def;  // static, at the origin
  b2Body* ground = world.CreateBody(&def);
  for (std::size_t k = 0; k < scene.walls.size(); ++k) {
    const WallDef& wall = scene.walls[k];
    b2EdgeShape edge;
    edge.SetTwoSided(toB2(wall.a), toB2(wall.b));
    // Box2D gives edges a skin of b2_polygonRadius (0.01 m), so a ball would
    // touch a wall 1 cm early. A scene wall is a line of no thickness, and a
    // circle-edge contact is exact with radius 0 (b2CollideEdgeAndCircle
    // compares the distance with the sum of the radii).
    edge.m_radius = 0.0f;
    b2FixtureDef fixture;
    fixture.shape = &edge;
    setMaterial(fixture, resolveMaterial(scene.contact, wall.restitution, wall.friction), settings);
    fixture.userData.pointer = k;
    out.push_back(ground->CreateFixture(&fixture));
  }
}

}  // namespace

// A world with at most two broad-phase proxies (two balls, or one ball and one
// wall) can be emptied and refilled instead of rebuilt, bit-identically: the
// suite's isolated cases are all of that size, and rebuilding would spend
// most of their Box2D time on the allocator (docs/box2d-twin.md, "Reuse").
bool Box2DWorld::Impl::canRefill(const SceneDef& scene) const {
  const std::size_t before = balls.size() + wallFixtures.size();
  const std::size_t after = scene.balls.size() + scene.walls.size();
  return world && before <= 2 && after <= 2;
}

// Destroying the bodies in the reverse of their creation order returns the
// dynamic tree's free list to 0, 1, 2, ... (each leaf and its parent go back
// onto it last-in first-out), so the refilled world hands out the same proxy
// ids as a fresh one, and its pair (fixture A, fixture B) is the same. A new
// contact has no impulse to warm-start, so the previous case's step ratio
// (b2World::m_inv_dt0) cannot reach the result.
void Box2DWorld::Impl::empty() {
  for (auto it = balls.rbegin(); it != balls.rend(); ++it) world->DestroyBody(*it);
  if (!wallFixtures.empty()) world->DestroyBody(wallFixtures.front()->GetBody());
}

void Box2DWorld::Impl::build(const SceneDef& scene) {
  validate(scene, settings);
  if (canRefill(scene)) {
    empty();
    world->SetGravity(toB2(scene.gravity));
  } else {
    // emplace destroys the old b2World (bodies, fixtures, contacts, broad
    // phase) and constructs a new one in the same storage: a fresh world.
    world.emplace(toB2(scene.gravity));
  }
  world->SetAllowSleeping(false);
  world->SetContinuousPhysics(settings.continuousPhysics);
  balls.clear();
  wallFixtures.clear();
  forces = scene.forces;
  stepIndex = 0;
  limitHits = {};
  addWalls(*world, scene, settings, wallFixtures);
  for (std::size_t i = 0; i < scene.balls.size(); ++i)
    balls.push_back(addBall(*world, scene, i, settings));
}

// Forces for this step, from the state at its start (as in the engine's
// World::applyForces). Box2D accumulates them and clears them after Step.
void Box2DWorld::Impl::applyForces() {
  const double t = static_cast<double>(stepIndex) * settings.dt;
  for (const ForceDef& f : forces) {
    if (!f.activeAt(t)) continue;
    b2Body* body = balls[static_cast<std::size_t>(f.ball)];
    if (f.type == ForceType::Pull) {
      const Vec2 centre = toVec2(body->GetPosition());
      body->ApplyForceToCenter(toB2(f.stiffness * (f.target - centre)), true);
    } else {
      body->ApplyForceToCenter(toB2(f.force), true);
      body->ApplyTorque(static_cast<float>(f.torque), true);
    }
  }
}

// b2Island::Solve scales a velocity down to exactly b2_maxTranslation /
// b2_maxRotation per step when it would exceed it, so a ball found at that
// bound (within float rounding) was clamped.
void Box2DWorld::Impl::countLimitHits() {
  constexpr double kAtBound = 1.0 - 1e-5;
  const double h = static_cast<float>(settings.dt);  // Box2D's own step, a float
  bool translation = false, rotation = false;
  for (const b2Body* body : balls) {
    const b2Vec2 v = body->GetLinearVelocity();
    translation = translation || h * v.Length() >= kAtBound * limits::kMaxTranslation;
    rotation =
        rotation || h * std::abs(body->GetAngularVelocity()) >= kAtBound * limits::kMaxRotation;
  }
  limitHits.translation += translation;
  limitHits.rotation += rotation;
}

Box2DWorld::Box2DWorld(const SceneDef& scene, const Box2DSettings& settings)
    : impl_(std::make_unique<Impl>()) {
  impl_->settings = settings;
  impl_->build(scene);
}

Box2DWorld::~Box2DWorld() = default;
Box2DWorld::Box2DWorld(Box2DWorld&&) noexcept = default;
Box2DWorld& Box2DWorld::operator=(Box2DWorld&&) noexcept = default;

void Box2DWorld::reset(const SceneDef& scene) {
  impl_->build(scene);
}

void Box2DWorld::step() {
  impl_->applyForces();
  impl_->world->Step(static_cast<float>(impl_->settings.dt), impl_->settings.velocityIterations,
                     impl_->settings.positionIterations);
  ++impl_->stepIndex;
  impl_->countLimitHits();
}

void Box2DWorld::run(long long steps) {
  for (long long s = 0; s < steps; ++s) step();
}

double Box2DWorld::time() const {
  return static_cast<double>(impl_->stepIndex) * impl_->settings.dt;
}
long long Box2DWorld::stepIndex() const {
  return impl_->stepIndex;
}
std::size_t Box2DWorld::ballCount() const {
  return impl_->balls.size();
}
std::size_t Box2DWorld::wallCount() const {
  return impl_->wallFixtures.size();
}
const Box2DSettings& Box2DWorld::settings() const {
  return impl_->settings;
}
const Box2DLimitHits& Box2DWorld::limitHits() const {
  return impl_->limitHits;
}

// The body origin is the ball's centre (the centre of mass is set there).
BallState Box2DWorld::ball(std::size_t i) const {
  const b2Body* body = impl_->balls.at(i);
  return {toVec2(body->GetPosition()), toVec2(body->GetLinearVelocity()), body->GetAngle(),
          body->GetAngularVelocity()};
}

std::vector<BallState> Box2DWorld::balls() const {
  std::vector<BallState> all(ballCount());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = ball(i);
  return all;
}

void Box2DWorld::setPullTarget(std::size_t force, const Vec2& target) {
  impl_->forces.at(force).target = target;
}

}  // namespace particles::reference
