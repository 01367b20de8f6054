// The same SceneDef gives the same bits: two Worlds built from it, run
// separately or interleaved, or a World copied mid-run, end in bit-identical
// states. Compared with memcmp, not a tolerance, plus a canonical hash that a
// failure prints.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "particles/world.h"
#include "physics_test_support.h"

namespace {

using namespace physics_test;

// Everything that can happen in a scene: gravity, walls, friction (mixed per
// ball), restitution overrides, spins, a pull and a constant force with a
// torque, enough balls for the grid.
particles::SceneDef busyScene() {
  particles::SceneDef scene;
  scene.gravity = Vec2(0.0, -9.81);
  scene.contact = particles::ContactMaterial{0.7, 0.4};
  scene.walls = particles::boxWalls(Vec2(0.0, 0.0), Vec2(16.0, 30.0));
  particles::WallDef ramp;
  ramp.a = Vec2(2.0, 12.0);
  ramp.b = Vec2(12.0, 8.0);
  ramp.friction = particles::kNoSlip;
  scene.walls.push_back(ramp);
  Random rand(0x5eed'0021);
  for (int i = 0; i < 150; ++i) {
    particles::BallDef b;
    b.radius = rand.uniform(0.15, 0.45);
    b.mass = rand.logUniform(0.5, 5.0);
    if (i % 5 == 0) b.inertia = 0.3 * b.mass * b.radius * b.radius;
    if (i % 7 == 0) b.restitution = 1.0;
    if (i % 11 == 0) b.friction = 0.0;
    b.position = Vec2(0.6 + 1.0 * (i % 15), 14.0 + 1.0 * (i / 15));
    b.velocity = Vec2(rand.uniform(-3.0, 3.0), rand.uniform(-3.0, 3.0));
    b.angularVelocity = rand.uniform(-10.0, 10.0);
    scene.balls.push_back(b);
  }
  particles::ForceDef pull;
  pull.type = particles::ForceType::Pull;
  pull.ball = 3;
  pull.target = Vec2(8.0, 20.0);
  pull.stiffness = 40.0;
  pull.end = 0.5;
  scene.forces.push_back(pull);
  particles::ForceDef spin;
  spin.type = particles::ForceType::Constant;
  spin.ball = 10;
  spin.force = Vec2(5.0, 0.0);
  spin.torque = 0.7;
  scene.forces.push_back(spin);
  scene.solver.gridThreshold = 48;  // 150 balls: the grid
  return scene;
}

// The state as one flat array of doubles, in ball order.
std::vector<double> state(const particles::World& w) {
  std::vector<double> s;
  for (std::size_t i = 0; i < w.ballCount(); ++i) {
    const particles::BallState b = w.ball(i);
    s.insert(s.end(), {b.position.x(), b.position.y(), b.velocity.x(), b.velocity.y(), b.angle,
                       b.angularVelocity});
  }
  return s;
}

// FNV-1a over the bit patterns, in ball order (x, y, vx, vy, angle, w).
std::uint64_t canonicalHash(const std::vector<double>& s) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (double d : s) {
    std::uint64_t bits;
    std::memcpy(&bits, &d, sizeof bits);
    for (int k = 0; k < 8; ++k) {
      h ^= (bits >> (8 * k)) & 0xffu;
      h *= 0x100000001b3ULL;
    }
  }
  return h;
}

void expectBitIdentical(const std::vector<double>& a, const std::vector<double>& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0)
      << "hash " << std::hex << canonicalHash(a) << " vs " << canonicalHash(b);
}

constexpr int kSteps = 1000;

TEST(Determinism, SameSceneTwiceGivesBitIdenticalStates) {
  const particles::SceneDef scene = busyScene();
  particles::World first(scene);
  first.run(kSteps);
  particles::World second(scene);
  second.run(kSteps);
  const std::vector<double> a = state(first), b = state(second);
  std::printf("[ measured ] state hash after %d steps: %016llx\n", kSteps,
              static_cast<unsigned long long>(canonicalHash(a)));
  expectBitIdentical(a, b);
  EXPECT_NE(a, state(particles::World(scene))) << "the scene must actually evolve";
}

// No hidden shared state between Worlds: stepping two in lockstep gives the
// same as stepping each alone.
TEST(Determinism, InterleavedWorldsGiveBitIdenticalStates) {
  const particles::SceneDef scene = busyScene();
  particles::World alone(scene);
  alone.run(kSteps);
  particles::World x(scene), y(scene);
  for (int s = 0; s < kSteps; ++s) {
    x.step();
    y.step();
  }
  expectBitIdentical(state(x), state(alone));
  expectBitIdentical(state(y), state(alone));
}

// A World is its own complete state: a copy taken mid-run continues exactly
// like the original (scratch buffers carry nothing between steps).
TEST(Determinism, CopiedWorldContinuesIdentically) {
  const particles::SceneDef scene = busyScene();
  particles::World original(scene);
  original.run(kSteps / 2);
  particles::World copy = original;
  original.run(kSteps / 2);
  copy.run(kSteps / 2);
  expectBitIdentical(state(copy), state(original));
}

}  // namespace
