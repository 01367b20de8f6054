// Contacts inside the World's step: resting contact, the position pass,
// simultaneous contacts (Newton's cradle, a corner), and the pass counters.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "particles/world.h"
#include "physics_test_support.h"

namespace {

using namespace physics_test;
using particles::ContactMaterial;

constexpr double kG = 9.81;

particles::WallDef segment(Vec2 a, Vec2 b) {
  particles::WallDef w;
  w.a = a;
  w.b = b;
  return w;
}

particles::SceneDef ballOnFloor(double e, double height, double dt) {
  particles::SceneDef scene;
  scene.gravity = Vec2(0.0, -kG);
  scene.contact = ContactMaterial{e, 0.3};
  scene.dt = dt;
  scene.walls.push_back(segment(Vec2(-10.0, 0.0), Vec2(10.0, 0.0)));
  particles::BallDef ball;
  ball.radius = 0.5;
  ball.mass = 1.7;
  ball.position = Vec2(0.0, 0.5 + height);
  scene.balls.push_back(ball);
  return scene;
}

// e = 0: each step gravity gives v_y = -g dt, the floor's impulse takes it
// back to 0 (to rounding, ~eps g dt), and the position never changes.
TEST(WorldContacts, InelasticBallRestsOnTheFloor) {
  const double dt = 1e-3;
  particles::World world(ballOnFloor(0.0, 0.0, dt));
  double worstY = 0.0, worstV = 0.0;
  for (int n = 1; n <= 5000; ++n) {
    world.step();
    const particles::BallState s = world.ball(0);
    worstY = std::max(worstY, std::abs(s.position.y() - 0.5));
    worstV = std::max(worstV, s.velocity.norm());
    ASSERT_NEAR(s.position.y(), 0.5, kRoundingRel * 0.5) << "step " << n;
    ASSERT_EQ(s.position.x(), 0.0) << "step " << n;
    ASSERT_LE(s.velocity.norm(), kRoundingRel * kG * dt) << "step " << n;
    ASSERT_LE(world.stats().maxOverlap, kRoundingRel * 0.5) << "step " << n;
  }
  std::printf("[ measured ] resting e = 0: max |y - r| = %.3e, max |v| = %.3e\n", worstY, worstV);
}

// 0 < e <= 1: resting is a train of micro-bounces. Each is fed by one step of
// gravity, g dt, and returns e times its landing speed; for e < 1 the speeds
// stay below the geometric sum (1 + e)/(1 - e) g dt (times 2 for the step in
// which a landing and the gravity kick coincide), heights below that times
// dt. Whatever e, a ball put at rest has (continuous) energy 0 and must not
// start hopping higher and higher: the jitter of the last second of a 10 s
// run must be no larger than that of the first second.
struct Jitter {
  double firstSecond = 0.0, lastSecond = 0.0, maxSpeed = 0.0;
  bool sank = false;
};

Jitter restingBallJitter(double e) {
  const double dt = 1e-3;
  particles::World world(ballOnFloor(e, 0.0, dt));
  Jitter j;
  for (int n = 1; n <= 10000; ++n) {
    world.step();
    const particles::BallState s = world.ball(0);
    const double height = std::abs(s.position.y() - 0.5);
    j.maxSpeed = std::max(j.maxSpeed, s.velocity.norm());
    j.sank = j.sank || s.position.y() - 0.5 < -1e-9 * 0.5;
    if (n <= 1000) j.firstSecond = std::max(j.firstSecond, height);
    if (n > 9000) j.lastSecond = std::max(j.lastSecond, height);
  }
  std::printf(
      "[ measured ] resting e = %g: max height first second %.3e m, last second %.3e m, "
      "max speed %.3e m/s\n",
      e, j.firstSecond, j.lastSecond, j.maxSpeed);
  return j;
}

TEST(WorldContacts, PartlyElasticRestingBallJitterStaysBounded) {
  const double dt = 1e-3, e = 0.5;
  const double vBound = 2.0 * (1.0 + e) / (1.0 - e) * kG * dt;
  const Jitter j = restingBallJitter(e);
  EXPECT_FALSE(j.sank);
  EXPECT_LE(j.maxSpeed, vBound);
  EXPECT_LE(j.firstSecond, vBound * dt);
  EXPECT_LE(j.lastSecond, j.firstSecond * 1.01);
}

// e = 1 is the default material (README, "Decisions").
TEST(WorldContacts, ElasticRestingBallJitterDoesNotGrow) {
  const Jitter j = restingBallJitter(1.0);
  EXPECT_FALSE(j.sank);
  EXPECT_LE(j.lastSecond, j.firstSecond * 1.01)
      << "a ball put at rest on the floor is hopping higher and higher";
}

// e = 1, dropped from 1 m (no sideways motion, so friction plays no part):
// energy should be conserved up to the scheme's first-order error, which does
// not accumulate in free flight (symplectic Euler conserves E - m g v dt/2
// exactly between bounces, so E itself wanders by at most m g |v| dt) and
// should not accumulate over bounces either: |E - E0| <= 2 m g v_max dt for
// all time.
TEST(WorldContacts, ElasticBouncingBallDoesNotGainEnergy) {
  const double dt = 1e-3, h = 1.0;
  particles::World world(ballOnFloor(1.0, h, dt));
  const double vMax = std::sqrt(2.0 * kG * h);
  const double E0 = kG * h;  // per unit mass, floor contact height as zero
  const double bound = 2.0 * kG * vMax * dt;
  double worst = 0.0, worstAt = 0.0;
  for (int n = 1; n <= 20000; ++n) {
    world.step();
    const particles::BallState s = world.ball(0);
    const double E = 0.5 * s.velocity.squaredNorm() + kG * (s.position.y() - 0.5);
    if (std::abs(E - E0) > worst) {
      worst = std::abs(E - E0);
      worstAt = world.time();
    }
  }
  std::printf("[ measured ] elastic bounce: max |E - E0| / E0 = %.3e at t = %.3f s (bound %.3e)\n",
              worst / E0, worstAt, bound / E0);
  EXPECT_LE(worst, bound) << "energy drifted by " << worst / E0 * 100.0 << " % of E0 within "
                          << worstAt << " s";
}

// Two balls that do not touch at the start of a step but overlap after the
// position update: the position pass separates them.
particles::SceneDef closingPair() {
  particles::SceneDef scene;
  scene.dt = 1e-3;
  particles::BallDef a, b;
  a.radius = 0.5;
  a.mass = 1.0;
  a.position = Vec2(0.0, 0.0);
  a.velocity = Vec2(10.0, 0.0);
  b.radius = 0.7;
  b.mass = 3.0;
  b.position = Vec2(1.21, 0.0);  // gap 0.01
  b.velocity = Vec2(-5.0, 0.0);  // closing 15 m/s: 0.015 in one step
  scene.balls = {a, b};
  return scene;
}

TEST(WorldContacts, PositionPassSeparatesBallsThatOverlapAfterTheStep) {
  particles::World world(closingPair());
  world.step();
  EXPECT_EQ(world.stats().contacts, 0) << "apart at the start of the step";
  // Overlap after x += v dt: 1.2 - (1.21 - 15 dt) = 0.005.
  EXPECT_NEAR(world.stats().maxOverlap, 0.005, 1e-14);
  const double gap = (world.ball(1).position - world.ball(0).position).norm() - 1.2;
  std::printf("[ measured ] after the position pass: |d| - (r_a + r_b) = %.3e\n", gap);
  EXPECT_GE(gap, -1e-9 * 1.2) << "overlap left above the documented tolerance";
  EXPECT_LE(std::abs(gap), kRoundingRel * 1.2);
}

// The projection moves positions only, in inverse proportion to mass: the
// velocities are untouched and the centre of mass moves as if nothing
// happened (m_a dx_a + m_b dx_b = -share + share = 0).
TEST(WorldContacts, PositionPassKeepsVelocitiesAndTheCentreOfMass) {
  const particles::SceneDef scene = closingPair();
  particles::World world(scene);
  world.step();
  EXPECT_EQ(world.ball(0).velocity, scene.balls[0].velocity);
  EXPECT_EQ(world.ball(1).velocity, scene.balls[1].velocity);
  auto centre = [](Vec2 xa, Vec2 xb) { return (1.0 * xa + 3.0 * xb) / 4.0; };
  const Vec2 before = centre(scene.balls[0].position, scene.balls[1].position);
  const Vec2 vcm = centre(scene.balls[0].velocity, scene.balls[1].velocity);
  const Vec2 after = centre(world.ball(0).position, world.ball(1).position);
  EXPECT_NEAR((after - (before + scene.dt * vcm)).norm(), 0.0, kRoundingRel);
}

// The next step finds them touching and approaching, and bounces them:
// e = 1 (default): momentum conserved, relative normal velocity reversed.
TEST(WorldContacts, SeparatedPairBouncesOnTheNextStep) {
  const particles::SceneDef scene = closingPair();
  particles::World world(scene);
  world.run(2);
  EXPECT_EQ(world.stats().contacts, 1);
  const Vec2 va = world.ball(0).velocity, vb = world.ball(1).velocity;
  EXPECT_NEAR((1.0 * va + 3.0 * vb - Vec2(10.0 - 15.0, 0.0)).norm(), 0.0, kRoundingRel * 25.0);
  EXPECT_NEAR(vb.x() - va.x(), 15.0, kRoundingRel * 15.0);
}

// Newton's cradle: n equal balls in a row, touching; the first one arrives
// from a gap with speed v0 (e = 1, mu = 0). Equal masses exchange velocities
// in an elastic head-on impact, so the momentum runs down the row and leaves
// in the last ball; the others end at rest.
particles::SceneDef cradle(int n, bool fromTheRight, int contactPasses) {
  particles::SceneDef scene;
  scene.dt = 1e-3;
  scene.contact = ContactMaterial{1.0, 0.0};
  scene.solver.contactPasses = contactPasses;
  for (int i = 0; i < n; ++i) {
    particles::BallDef b;
    b.radius = 0.5;
    b.mass = 1.0;
    b.position = Vec2(static_cast<double>(i), 0.0);  // touching neighbours
    scene.balls.push_back(b);
  }
  if (fromTheRight) {
    scene.balls.back().position.x() += 0.2;
    scene.balls.back().velocity = Vec2(-1.0, 0.0);
  } else {
    scene.balls.front().position.x() -= 0.2;
    scene.balls.front().velocity = Vec2(1.0, 0.0);
  }
  return scene;
}

void expectCradleOutcome(const particles::World& world, bool fromTheRight) {
  const int n = static_cast<int>(world.ballCount());
  const int leaver = fromTheRight ? 0 : n - 1;
  Vec2 p(0.0, 0.0);
  double E = 0.0;
  for (int i = 0; i < n; ++i) {
    const Vec2 v = world.ball(i).velocity;
    p += v;
    E += 0.5 * v.squaredNorm();
    if (i == leaver) {
      EXPECT_NEAR(v.x(), fromTheRight ? -1.0 : 1.0, kRoundingRel) << "ball " << i << " of " << n;
    } else {
      EXPECT_NEAR(v.norm(), 0.0, kRoundingRel) << "ball " << i << " of " << n;
    }
    EXPECT_EQ(world.ball(i).angularVelocity, 0.0);
  }
  EXPECT_NEAR((p - Vec2(fromTheRight ? -1.0 : 1.0, 0.0)).norm(), 0.0, kRoundingRel);
  EXPECT_NEAR(E, 0.5, kRoundingRel);
}

TEST(WorldContacts, NewtonsCradlePassesTheVelocityToTheLastBall) {
  for (int n = 3; n <= 5; ++n) {
    particles::World world(cradle(n, false, 64));
    world.run(1000);
    expectCradleOutcome(world, false);
    EXPECT_EQ(world.stats().passLimitHits, 0);
  }
}

// Coming from the right, against the order of the contact list, each pass
// moves the momentum one ball on: the impact step needs n - 1 passes.
TEST(WorldContacts, ReverseCradleTakesOnePassPerContact) {
  for (int n = 3; n <= 5; ++n) {
    particles::World world(cradle(n, true, 64));
    int impactPasses = 0;
    for (int s = 0; s < 1000; ++s) {
      world.step();
      impactPasses = std::max(impactPasses, world.stats().passes);
    }
    EXPECT_EQ(impactPasses, n - 1) << n << " balls";
    EXPECT_EQ(world.stats().passLimitHits, 0);
    expectCradleOutcome(world, true);
  }
}

// passLimitHits counts the steps that end at the pass bound with a contact
// still approaching: n - 1 passes are exactly enough for the reverse cradle,
// fewer are not.
TEST(WorldContacts, PassLimitHitsCountsStepsThatRunOutOfPasses) {
  const int n = 5;
  for (int passes = 1; passes <= n; ++passes) {
    particles::World world(cradle(n, true, passes));
    world.run(1000);
    if (passes >= n - 1) {
      EXPECT_EQ(world.stats().passLimitHits, 0) << passes << " passes";
    } else {
      EXPECT_GE(world.stats().passLimitHits, 1) << passes << " passes";
    }
    // Still a sequence of momentum-conserving elastic exchanges.
    Vec2 p(0.0, 0.0);
    double E = 0.0;
    for (int i = 0; i < n; ++i) {
      p += world.ball(i).velocity;
      E += 0.5 * world.ball(i).velocity.squaredNorm();
    }
    EXPECT_NEAR((p - Vec2(-1.0, 0.0)).norm(), 0.0, kRoundingRel) << passes << " passes";
    EXPECT_NEAR(E, 0.5, kRoundingRel) << passes << " passes";
  }
}

// A ball in a corner of two walls (floor and left wall of a box), e = 1,
// mu = 0: each wall reverses the velocity component along its normal and
// leaves the other alone, so both components come out reversed.
particles::SceneDef ballInBox(Vec2 x, Vec2 v) {
  particles::SceneDef scene;
  scene.dt = 1e-3;
  scene.contact = ContactMaterial{1.0, 0.0};
  scene.walls = particles::boxWalls(Vec2(0.0, 0.0), Vec2(10.0, 10.0));
  particles::BallDef b;
  b.radius = 0.5;
  b.position = x;
  b.velocity = v;
  scene.balls.push_back(b);
  return scene;
}

TEST(WorldContacts, BallInACornerComesOutWithBothComponentsReversed) {
  {
    // Touching both walls at once: one step.
    particles::World world(ballInBox(Vec2(0.5, 0.5), Vec2(-2.0, -3.0)));
    world.step();
    EXPECT_EQ(world.stats().contacts, 2);
    EXPECT_NEAR((world.ball(0).velocity - Vec2(2.0, 3.0)).norm(), 0.0, kRoundingRel * 5.0);
  }
  // Arriving from inside the box: at the corner together (x and y reach 0.5
  // at t = 0.5 s), or at different times (left wall at 0.5 s, floor at 1.25 s).
  const std::pair<Vec2, Vec2> starts[] = {{Vec2(2.0, 2.0), Vec2(-3.0, -3.0)},
                                          {Vec2(2.0, 3.0), Vec2(-3.0, -2.0)}};
  for (const auto& [x, v] : starts) {
    particles::World world(ballInBox(x, v));
    world.run(2000);  // 2 s: both walls hit, nothing else reached
    EXPECT_NEAR((world.ball(0).velocity + v).norm(), 0.0, kRoundingRel * 5.0)
        << "v = (" << v.x() << ", " << v.y() << ")";
    EXPECT_NEAR(world.ball(0).velocity.squaredNorm(), v.squaredNorm(), kRoundingRel * 25.0);
  }
}

// Many balls colliding at once, with every kind of material: the step is a
// sequence of two-body exchanges (Gauss-Seidel passes) plus a position pass
// that leaves velocities alone, so the invariants of a single impact carry
// over to the whole step: without walls and external forces the total
// momentum is conserved, and kinetic energy never grows (with walls too).
particles::SceneDef crowd(bool walls) {
  particles::SceneDef scene;
  scene.dt = 1e-3;
  scene.contact = ContactMaterial{0.9, 0.3};
  if (walls) scene.walls = particles::boxWalls(Vec2(-1.0, -1.0), Vec2(11.0, 11.0));
  Random rand(0x5eed'0051);
  const double frictions[] = {0.0, 0.3, particles::kNoSlip};
  for (int i = 0; i < 64; ++i) {
    particles::BallDef b;
    b.radius = rand.uniform(0.3, 0.55);
    b.mass = rand.logUniform(0.2, 5.0);
    if (i % 3 == 0) b.inertia = rand.uniform(0.1, 1.0) * b.mass * b.radius * b.radius;
    b.restitution = rand.uniform(0.0, 1.0);
    b.friction = frictions[i % 3];
    b.position = Vec2(0.6 + 1.2 * (i % 8), 0.6 + 1.2 * (i / 8));
    b.velocity = Vec2(rand.uniform(-5.0, 5.0), rand.uniform(-5.0, 5.0));
    b.angularVelocity = rand.uniform(-10.0, 10.0);
    scene.balls.push_back(b);
  }
  return scene;
}

TEST(WorldContacts, ManyBallCollisionsConserveMomentumEveryStep) {
  const particles::SceneDef scene = crowd(false);
  particles::World world(scene);
  auto total = [&] {
    Vec2 p(0.0, 0.0);
    double scale = 0.0;
    for (std::size_t i = 0; i < world.ballCount(); ++i) {
      p += scene.balls[i].mass * world.ball(i).velocity;
      scale += scene.balls[i].mass * world.ball(i).velocity.norm();
    }
    return std::pair{p, scale};
  };
  const auto [p0, scale0] = total();
  long long contacts = 0;
  double worst = 0.0;
  for (int s = 1; s <= 1000; ++s) {
    world.step();
    contacts += world.stats().contacts;
    const auto [p, scale] = total();
    // Rounding: each exchange adds ~eps of the momenta involved; over s steps
    // of at most a few hundred exchanges, 1e-12 of the momentum scale.
    worst = std::max(worst, (p - p0).norm() / scale0);
    ASSERT_LE((p - p0).norm(), kRoundingRel * std::max(scale, scale0)) << "step " << s;
  }
  std::printf("[ measured ] crowd: %lld contacts, max |P - P0| / sum m|v| = %.3e\n", contacts,
              worst);
  EXPECT_GT(contacts, 100) << "the crowd must actually collide";
}

TEST(WorldContacts, ManyBallCollisionsNeverGainKineticEnergy) {
  const particles::SceneDef scene = crowd(true);
  particles::World world(scene);
  auto energy = [&] {
    double E = 0.0;
    for (std::size_t i = 0; i < world.ballCount(); ++i) {
      const particles::BallDef& b = scene.balls[i];
      const particles::BallState s = world.ball(i);
      E += 0.5 * b.mass * s.velocity.squaredNorm() +
           0.5 * b.resolvedInertia() * s.angularVelocity * s.angularVelocity;
    }
    return E;
  };
  double E = energy();
  const double E0 = E;
  long long contacts = 0;
  for (int s = 1; s <= 2000; ++s) {
    world.step();
    contacts += world.stats().contacts;
    const double next = energy();
    ASSERT_LE(next, E * (1.0 + kRoundingRel)) << "step " << s;
    E = next;
  }
  std::printf("[ measured ] crowd in a box: kinetic energy %.4g -> %.4g J over 2 s\n", E0, E);
  EXPECT_GT(contacts, 100) << "the crowd must actually collide";
  EXPECT_LT(E, 0.9 * E0) << "inelastic, frictional collisions must dissipate";
}

// Coulomb at the scale of a whole step: the impulses a contact exchanged over
// all passes sum to |sum lambda_t| <= sum mu lambda_n (each pass obeys its own
// bound), and the normal impulse only ever pushes.
TEST(WorldContacts, RecordedImpactsRespectTheCoulombBound) {
  particles::World world(crowd(true));
  world.recordImpacts(true);
  long long events = 0, sliding = 0;
  for (int s = 1; s <= 2000; ++s) {
    world.step();
    for (const particles::ImpactEvent& e : world.impacts()) {
      ++events;
      ASSERT_GT(e.normalImpulse, 0.0) << "step " << s;
      ASSERT_LE(std::abs(e.tangentImpulse), e.frictionBound * (1.0 + kRoundingRel))
          << "step " << s << ", balls " << e.a << ", " << e.b << (e.wall ? " (wall)" : "");
      sliding += std::abs(e.tangentImpulse) >= e.frictionBound * (1.0 - 1e-9);
    }
  }
  std::printf("[ measured ] crowd: %lld impacts recorded, %lld at the Coulomb bound\n", events,
              sliding);
  EXPECT_GT(events, 200);
  EXPECT_GT(sliding, 10) << "some impacts must slide, or the bound was never tested";
}

}  // namespace
