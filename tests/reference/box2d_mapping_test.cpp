// The Box2D world matches its scene: bodies, mass properties, materials,
// walls, and Box2D's own mixing of two fixtures' materials at a contact.
#include <gtest/gtest.h>

#include <cmath>

#include "particles/reference/box2d_world.h"
#include "reference_test_support.h"

namespace particles::reference {
namespace {

using testing::asFloat;
using testing::ball;
using testing::openScene;

TEST(Box2DMapping, BodiesMatchTheScene) {
  BallDef a = ball({0.3, -0.2}, {1.5, -0.7}, 0.4, 2.5);
  a.angle = 0.7;
  a.angularVelocity = -3.1;
  BallDef b = ball({2.0, 1.0}, {0.0, 0.1}, 0.25, 0.3);
  b.inertia = 0.05;  // not a disk (a disk would be 0.3 * 0.25^2 / 2 = 0.009375)
  const SceneDef scene = openScene({a, b});
  const Box2DWorld world(scene, Box2DSettings::forScene(scene));

  ASSERT_EQ(world.ballCount(), 2u);
  EXPECT_EQ(world.wallCount(), 0u);
  EXPECT_EQ(world.settings().dt, scene.dt);
  EXPECT_EQ(world.time(), 0.0);
  for (std::size_t i = 0; i < 2; ++i) {
    const BallDef& def = scene.balls[i];
    const BallState s = world.ball(i);
    // Box2D stores floats: the state reads back as the scene's values rounded
    // to float, exactly (SetMassData must not disturb the velocities).
    EXPECT_EQ(s.position.x(), asFloat(def.position.x()));
    EXPECT_EQ(s.position.y(), asFloat(def.position.y()));
    EXPECT_EQ(s.velocity.x(), asFloat(def.velocity.x()));
    EXPECT_EQ(s.velocity.y(), asFloat(def.velocity.y()));
    EXPECT_EQ(s.angle, asFloat(def.angle));
    EXPECT_EQ(s.angularVelocity, asFloat(def.angularVelocity));

    const BodyInfo info = world.bodyInfo(i);
    EXPECT_TRUE(info.dynamic);
    EXPECT_EQ(info.mass, asFloat(def.mass));
    // Set explicitly about the centre (centre of mass at the body origin), so
    // exact whatever a density would have given.
    EXPECT_EQ(info.inertia, asFloat(def.resolvedInertia()));
    EXPECT_EQ(info.localCenter, Vec2(0.0, 0.0));
    EXPECT_EQ(info.radius, asFloat(def.radius));
    EXPECT_EQ(info.shapeOffset, Vec2(0.0, 0.0));
    EXPECT_EQ(info.linearDamping, 0.0);
    EXPECT_EQ(info.angularDamping, 0.0);
    EXPECT_EQ(info.gravityScale, 1.0);
    EXPECT_FALSE(info.bullet);
    EXPECT_FALSE(info.sleepingAllowed);
    EXPECT_FALSE(info.fixedRotation);
    EXPECT_TRUE(info.awake);
  }
  EXPECT_EQ(world.bodyInfo(0).inertia, asFloat(0.5 * 2.5 * 0.4 * 0.4));
  EXPECT_EQ(world.bodyInfo(1).inertia, asFloat(0.05));
}

TEST(Box2DMapping, FixturesCarryTheirBodysOwnMaterial) {
  BallDef plain = ball({0.0, 0.0}, {0.0, 0.0});
  BallDef own = ball({2.0, 0.0}, {0.0, 0.0});
  own.friction = 0.8;
  own.restitution = 0.3;
  BallDef grip = ball({4.0, 0.0}, {0.0, 0.0});
  grip.friction = kNoSlip;
  SceneDef scene = openScene({plain, own, grip}, {0.6, 0.4});
  scene.walls = boxWalls({-1.0, -1.0}, {5.0, 1.0});
  scene.walls[2].friction = 0.1;
  scene.walls[2].restitution = 0.9;
  const Box2DSettings settings = Box2DSettings::forScene(scene);
  const Box2DWorld world(scene, settings);

  EXPECT_EQ(world.bodyInfo(0).friction, asFloat(0.4));
  EXPECT_EQ(world.bodyInfo(0).restitution, asFloat(0.6));
  EXPECT_EQ(world.bodyInfo(1).friction, asFloat(0.8));
  EXPECT_EQ(world.bodyInfo(1).restitution, asFloat(0.3));
  // No-slip (infinity) becomes the finite stand-in.
  EXPECT_EQ(world.bodyInfo(2).friction, asFloat(settings.noSlipFriction));
  EXPECT_EQ(world.bodyInfo(2).restitution, asFloat(0.6));
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(world.bodyInfo(i).restitutionThreshold, 0.0);

  ASSERT_EQ(world.wallCount(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    const WallInfo w = world.wallInfo(k);
    EXPECT_EQ(w.a.x(), asFloat(scene.walls[k].a.x()));
    EXPECT_EQ(w.a.y(), asFloat(scene.walls[k].a.y()));
    EXPECT_EQ(w.b.x(), asFloat(scene.walls[k].b.x()));
    EXPECT_EQ(w.b.y(), asFloat(scene.walls[k].b.y()));
    EXPECT_TRUE(w.twoSided);
    EXPECT_EQ(w.radius, 0.0);  // no skin: a ball touches the wall at distance r
    EXPECT_EQ(w.restitutionThreshold, 0.0);
    EXPECT_EQ(w.friction, asFloat(k == 2 ? 0.1 : 0.4));
    EXPECT_EQ(w.restitution, asFloat(k == 2 ? 0.9 : 0.6));
  }
}

// Box2D mixes two fixtures at contact creation (b2Contact's constructor);
// reading the contacts after one step shows the values it actually uses.
// sqrt in float is correctly rounded, so one float ulp covers the difference
// with the engine's double mixFriction of the same float inputs.
TEST(Box2DMapping, ContactMixingEqualsTheEnginesRules) {
  // Balls 0-1 overlap by 1e-3 m; ball 2 overlaps the floor wall; ball 3
  // (no-slip) overlaps ball 4 (mu 0.25); ball 5 (smooth) overlaps ball 6 (no-slip).
  auto at = [](double x, double y) { return ball({x, y}, {0.0, 0.0}); };
  std::vector<BallDef> balls = {at(0.0, 3.0),   at(0.999, 3.0), at(3.0, 0.4995), at(6.0, 3.0),
                                at(6.999, 3.0), at(10.0, 3.0),  at(10.999, 3.0)};
  balls[0].friction = 0.3;
  balls[0].restitution = 0.2;
  balls[1].friction = 0.7;
  balls[1].restitution = 0.9;
  balls[2].friction = 0.5;
  balls[2].restitution = 0.1;
  balls[3].friction = kNoSlip;
  balls[4].friction = 0.25;
  balls[5].friction = 0.0;
  balls[6].friction = kNoSlip;
  SceneDef scene = openScene(balls, {0.5, 0.6});
  WallDef floor;
  floor.a = {-1.0, 0.0};
  floor.b = {12.0, 0.0};
  floor.friction = 0.2;
  floor.restitution = 0.4;
  scene.walls = {floor};
  Box2DWorld world(scene, Box2DSettings::forScene(scene));
  world.step();

  auto own = [&](int i) {
    return resolveMaterial(scene.contact, scene.balls[i].restitution, scene.balls[i].friction);
  };
  const ContactMaterial wallOwn = resolveMaterial(scene.contact, floor.restitution, floor.friction);
  int seen = 0;
  for (const ContactInfo& c : world.contacts()) {
    if (!c.touching) continue;
    ++seen;
    const ContactMaterial engine = mixMaterials(own(c.a), c.wall ? wallOwn : own(c.b));
    EXPECT_EQ(c.restitution, asFloat(engine.restitution)) << c.a << "-" << c.b;
    EXPECT_EQ(c.restitutionThreshold, 0.0);
    if (std::isinf(engine.friction)) {
      // sqrt(1e12 * 0.25) = 5e5 here: far above any ratio of tangential to
      // normal impulse a real contact needs, so it never clamps.
      EXPECT_GE(c.friction, 1e5) << c.a << "-" << c.b;
    } else {
      EXPECT_NEAR(c.friction, engine.friction, 2.0 * testing::floatUlp(engine.friction))
          << c.a << "-" << c.b;
    }
  }
  EXPECT_EQ(seen, 4);  // 0-1, 2-floor, 3-4, 5-6 (smooth: mixes to exactly 0)
}

TEST(Box2DMapping, WallsHaveNoSkin) {
  // A ball 5 mm above a floor (inside Box2D's default 1 cm edge skin) sliding
  // along it: with the twin's zero skin it does not touch and keeps its
  // velocity; another ball 1 mm into the floor does touch.
  SceneDef scene = openScene({ball({0.0, 0.505}, {1.0, 0.0}), ball({3.0, 0.499}, {1.0, 0.0})});
  WallDef floor;
  floor.a = {-2.0, 0.0};
  floor.b = {5.0, 0.0};
  scene.walls = {floor};
  Box2DWorld world(scene, Box2DSettings::forScene(scene));
  world.step();
  for (const ContactInfo& c : world.contacts()) {
    ASSERT_TRUE(c.wall);
    EXPECT_EQ(c.touching, c.a == 1) << "ball " << c.a;
  }
  EXPECT_EQ(world.ball(0).velocity.y(), 0.0);
  EXPECT_EQ(world.ball(0).position.y(), asFloat(0.505));
}

TEST(Box2DMapping, RejectsWhatBox2DCannotRepresent) {
  const SceneDef ok = openScene({ball({0.0, 0.0}, {0.0, 0.0})});
  Box2DSettings settings = Box2DSettings::forScene(ok);
  EXPECT_NO_THROW(Box2DWorld(ok, settings));

  SceneDef massless = ok;
  massless.balls[0].mass = 0.0;
  EXPECT_THROW(Box2DWorld(massless, settings), std::invalid_argument);
  SceneDef noInertia = ok;
  noInertia.balls[0].inertia = 0.0;
  EXPECT_THROW(Box2DWorld(noInertia, settings), std::invalid_argument);
  SceneDef orphanForce = ok;
  orphanForce.forces.push_back(ForceDef{});
  orphanForce.forces[0].ball = 1;
  EXPECT_THROW(Box2DWorld(orphanForce, settings), std::invalid_argument);
  settings.dt = 0.0;
  EXPECT_THROW(Box2DWorld(ok, settings), std::invalid_argument);
}

}  // namespace
}  // namespace particles::reference
