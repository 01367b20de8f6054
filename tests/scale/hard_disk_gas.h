// The elastic or inelastic gas of equal smooth hard disks, and the closed
// forms its statistics are checked against (../shared/PHYSICS-REFERENCES.md,
// "Many bodies"; derivations in docs/scale.md, "The hard-disk gas"). Written
// here, apart from the engine: the tests compare the engine's gas with these.
//
// Units: k_B = 1, so the temperature T is the mean kinetic energy per disk
// (two degrees of freedom, T/2 each): T = m <|v|^2> / 2, in J.
#pragma once

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "particles/scene.h"
#include "particles/world.h"

namespace particles::test {

// Henderson (1975): the pair distribution at contact of hard disks at area
// fraction phi, good to about 1 % up to phi = 0.5.
inline double hendersonContactValue(double phi) {
  return (1.0 - 7.0 * phi / 16.0) / ((1.0 - phi) * (1.0 - phi));
}

// The compressibility factor Z = P A / (N T) = 1 + 2 phi g2 (the virial of
// hard disks), which with Henderson's g2 is (1 + phi^2 / 8) / (1 - phi)^2.
inline double hendersonCompressibility(double phi) {
  return 1.0 + 2.0 * phi * hendersonContactValue(phi);
}

// Enskog's collision frequency per disk (1/s) of disks of diameter sigma (m)
// and mass m (kg) at area fraction phi and temperature T (J): the density
// 4 phi / (pi sigma^2) times the cross-section 2 sigma times g2 times the
// mean relative speed sqrt(pi T / m) of two Maxwellian disks.
inline double enskogCollisionRate(double phi, double sigma, double m, double T) {
  return 8.0 * phi * hendersonContactValue(phi) / sigma * std::sqrt(T / (std::numbers::pi * m));
}

// Haff's law for smooth disks of restitution e: T(t) = T0 / (1 + t / tau)^2,
// 1 / tau = (1 - e^2) f(T0) / 4 (each collision loses (1 - e^2) T on
// average, and there are N f / 2 of them per unit time).
inline double haffTemperature(double T0, double tau, double t) {
  return T0 / ((1.0 + t / tau) * (1.0 + t / tau));
}

// side x side disks of radius 0.5 m and mass 1 kg on a square lattice in a
// square box of four walls, the box sized for area fraction phi; every disk
// at speed v0 (m/s) in a random direction (seeded), the mean momentum taken
// out. Smooth (mu = 0), restitution e, no gravity: from 1,000 disks the
// large-scene path.
struct HardDiskGas {
  SceneDef scene;
  double side = 0.0;  // m, the box's side
};

inline HardDiskGas hardDiskGas(int side, double phi, double e, double dt, double v0,
                               unsigned seed) {
  HardDiskGas g;
  const int n = side * side;
  const double r = 0.5;
  g.side = std::sqrt(n * std::numbers::pi * r * r / phi);
  SceneDef& s = g.scene;
  s.dt = dt;
  s.contact = {e, 0.0};
  s.walls = boxWalls({0.0, 0.0}, {g.side, g.side});
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> turn(0.0, 2.0 * std::numbers::pi);
  const double spacing = g.side / side;
  Vec2 mean(0.0, 0.0);
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      BallDef b;
      b.radius = r;
      b.mass = 1.0;
      b.position = {(i + 0.5) * spacing, (j + 0.5) * spacing};
      const double a = turn(rng);
      b.velocity = {v0 * std::cos(a), v0 * std::sin(a)};
      mean += b.velocity;
      s.balls.push_back(b);
    }
  mean /= n;
  for (BallDef& b : s.balls) b.velocity -= mean;
  return g;
}

// The scene started from a state of its balls (a relaxed gas): positions
// and velocities from `balls`, in the scene's order.
inline void startFrom(SceneDef& scene, const std::vector<BallState>& balls) {
  for (std::size_t i = 0; i < balls.size(); ++i) {
    scene.balls[i].position = balls[i].position;
    scene.balls[i].velocity = balls[i].velocity;
  }
}

// The mean kinetic energy per disk, J (all disks of mass 1 kg here).
inline double temperature(const std::vector<BallState>& balls) {
  double sum = 0.0;
  for (const BallState& b : balls) sum += 0.5 * b.velocity.squaredNorm();
  return sum / static_cast<double>(balls.size());
}

}  // namespace particles::test
