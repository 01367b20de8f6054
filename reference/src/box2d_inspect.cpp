// Reading the twin's Box2D objects back for tests (box2d_inspect.h): what
// Box2D holds, not what the twin meant to give it.
#include "particles/reference/box2d_inspect.h"

#include <utility>

#include "box2d_world_impl.h"

namespace particles::reference {

BodyInfo Box2DWorld::bodyInfo(std::size_t ball) const {
  b2Body* body = impl_->balls.at(ball);
  b2Fixture* fixture = body->GetFixtureList();
  const auto* circle = static_cast<const b2CircleShape*>(fixture->GetShape());
  BodyInfo info;
  info.dynamic = body->GetType() == b2_dynamicBody;
  info.mass = body->GetMass();
  info.inertia = body->GetInertia();
  info.localCenter = toVec2(body->GetLocalCenter());
  info.radius = circle->m_radius;
  info.shapeOffset = toVec2(circle->m_p);
  info.friction = fixture->GetFriction();
  info.restitution = fixture->GetRestitution();
  info.restitutionThreshold = fixture->GetRestitutionThreshold();
  info.linearDamping = body->GetLinearDamping();
  info.angularDamping = body->GetAngularDamping();
  info.gravityScale = body->GetGravityScale();
  info.bullet = body->IsBullet();
  info.sleepingAllowed = body->IsSleepingAllowed() && impl_->world->GetAllowSleeping();
  info.fixedRotation = body->IsFixedRotation();
  info.awake = body->IsAwake();
  return info;
}

WallInfo Box2DWorld::wallInfo(std::size_t wall) const {
  b2Fixture* fixture = impl_->wallFixtures.at(wall);
  const auto* edge = static_cast<const b2EdgeShape*>(fixture->GetShape());
  const b2Body* body = fixture->GetBody();
  WallInfo info;
  info.a = toVec2(body->GetWorldPoint(edge->m_vertex1));
  info.b = toVec2(body->GetWorldPoint(edge->m_vertex2));
  info.twoSided = !edge->m_oneSided;
  info.radius = edge->m_radius;
  info.friction = fixture->GetFriction();
  info.restitution = fixture->GetRestitution();
  info.restitutionThreshold = fixture->GetRestitutionThreshold();
  return info;
}

std::vector<ContactInfo> Box2DWorld::contacts() const {
  std::vector<ContactInfo> out;
  for (b2Contact* c = impl_->world->GetContactList(); c != nullptr; c = c->GetNext()) {
    b2Fixture* fa = c->GetFixtureA();
    b2Fixture* fb = c->GetFixtureB();
    // Box2D orders a circle-edge contact edge first; the twin reports the ball
    // first, and two balls by index.
    if (fa->GetBody()->GetType() == b2_staticBody) std::swap(fa, fb);
    ContactInfo info;
    info.wall = fb->GetBody()->GetType() == b2_staticBody;
    info.a = fixtureIndex(fa);
    info.b = fixtureIndex(fb);
    if (!info.wall && info.b < info.a) std::swap(info.a, info.b);
    info.touching = c->IsTouching();
    info.friction = c->GetFriction();
    info.restitution = c->GetRestitution();
    info.restitutionThreshold = c->GetRestitutionThreshold();
    const b2Manifold* manifold = c->GetManifold();
    for (int p = 0; p < manifold->pointCount; ++p) {
      info.normalImpulse += manifold->points[p].normalImpulse;
      info.tangentImpulse += manifold->points[p].tangentImpulse;
    }
    out.push_back(info);
  }
  return out;
}

}  // namespace particles::reference
