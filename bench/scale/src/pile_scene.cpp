#include "particles/pile/pile_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace particles::pile {
namespace {

// SplitMix64: a fully specified generator, so a seed gives the same scene
// with every compiler and standard library (std:: distributions are not
// specified bit for bit).
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // Uniform in [0, 1), 53 bits.
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }

 private:
  std::uint64_t state_;
};

}  // namespace

PileGeometry pileGeometry(int count) {
  if (count < 1) throw std::invalid_argument("pile: count must be >= 1");
  PileGeometry g;
  const double n = static_cast<double>(count);
  g.width = kWidthPerRootN * std::sqrt(n);
  // At least one cell, even for a box narrower than a spacing (N = 1).
  g.columns = std::max(1, static_cast<int>(std::floor(g.width / kSpacing)));
  g.width = std::max(g.width, g.columns * kSpacing);
  g.rows = (count + g.columns - 1) / g.columns;
  g.gridLeft = 0.5 * (g.width - g.columns * kSpacing);
  g.gridBottom = 0.5 * kSpacing;
  // Settled height from the disks' area at the assumed packing fraction (mean
  // disk area pi r^2 with r = 0.5 m; the polydisperse mean of r^2 is 0.2533,
  // 1.3 % more, which the fill fraction's "about" covers).
  const double diskArea = n * std::numbers::pi * kRadius * kRadius;
  const double settled = diskArea / (kPackingFraction * g.width);
  const double gridTop = g.gridBottom + g.rows * kSpacing;
  g.height = std::max(settled / kFillFraction, gridTop + kSpacing);
  return g;
}

SceneDef makePile(const PileParams& params) {
  const PileGeometry g = pileGeometry(params.count);
  SceneDef scene;
  scene.name = params.polydisperse ? "pile-polydisperse" : "pile";
  scene.gravity = Vec2(0.0, kGravity);
  scene.contact = ContactMaterial{0.5, 0.5};
  scene.walls = boxWalls(Vec2(0.0, 0.0), Vec2(g.width, g.height));
  scene.dt = kTimeStep;
  scene.duration = 600 * kTimeStep;
  scene.solver.threads = params.threads;
  scene.balls.reserve(static_cast<std::size_t>(params.count));
  SplitMix64 random(params.seed);
  for (int i = 0; i < params.count; ++i) {
    BallDef b;
    b.radius = params.polydisperse ? random.uniform(kMinRadius, kMaxRadius) : kRadius;
    b.mass = kDensity * std::numbers::pi * b.radius * b.radius;
    // The disk stays inside its own cell: no overlap with any other disk.
    const double room = 0.5 * kSpacing - b.radius;
    const double cx = g.gridLeft + ((i % g.columns) + 0.5) * kSpacing;
    const double cy = g.gridBottom + ((i / g.columns) + 0.5) * kSpacing;
    const double jx = random.uniform(-room, room), jy = random.uniform(-room, room);
    b.position = Vec2(cx + jx, cy + jy);
    scene.balls.push_back(b);
  }
  return scene;
}

}  // namespace particles::pile
