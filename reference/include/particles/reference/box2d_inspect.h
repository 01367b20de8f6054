// What the twin's Box2D objects actually hold, read back from b2Body,
// b2Fixture and b2Contact, so that tests can check the mapping without
// including Box2D. All values are Box2D's floats widened to double.
#pragma once

#include "particles/types.h"

namespace particles::reference {

// One ball's b2Body and its single b2CircleShape fixture.
struct BodyInfo {
  bool dynamic = false;
  double mass = 0.0;                  // kg, b2Body::GetMass
  double inertia = 0.0;               // kg m^2, b2Body::GetInertia (about the origin = centre)
  Vec2 localCenter{0.0, 0.0};         // m, centre of mass in body coordinates
  double radius = 0.0;                // m, b2CircleShape::m_radius
  Vec2 shapeOffset{0.0, 0.0};         // m, b2CircleShape::m_p (circle centre in body coordinates)
  double friction = 0.0;              // b2Fixture::GetFriction
  double restitution = 0.0;           // b2Fixture::GetRestitution
  double restitutionThreshold = 0.0;  // m/s, b2Fixture::GetRestitutionThreshold
  double linearDamping = 0.0;         // 1/s
  double angularDamping = 0.0;        // 1/s
  double gravityScale = 0.0;
  bool bullet = false;
  bool sleepingAllowed = false;  // body and world both allow sleep (else it never sleeps)
  bool fixedRotation = false;
  bool awake = false;
};

// One wall's b2EdgeShape fixture (all walls hang on one static body).
struct WallInfo {
  Vec2 a{0.0, 0.0};  // m, vertex 1 in world coordinates
  Vec2 b{0.0, 0.0};  // m, vertex 2 in world coordinates
  bool twoSided = false;
  double radius = 0.0;  // m, the edge's skin (b2Shape::m_radius)
  double friction = 0.0;
  double restitution = 0.0;
  double restitutionThreshold = 0.0;  // m/s
};

// One b2Contact of the world's contact list: Box2D's own mixed material.
struct ContactInfo {
  bool wall = false;  // false: ball a against ball b; true: ball a against wall b
  int a = 0;          // ball index (the lower one for two balls)
  int b = 0;          // ball or wall index
  bool touching = false;
  double friction = 0.0;              // b2Contact::GetFriction (b2MixFriction)
  double restitution = 0.0;           // b2Contact::GetRestitution (b2MixRestitution)
  double restitutionThreshold = 0.0;  // m/s, b2Contact::GetRestitutionThreshold
  double normalImpulse = 0.0;         // N s, summed over manifold points, last step
  double tangentImpulse = 0.0;        // N s, likewise, in Box2D's frame (fixture A to B)
};

}  // namespace particles::reference
