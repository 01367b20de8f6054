#include "bench_skip_study.h"

#include <cmath>
#include <cstdint>
#include <numbers>

#include "bench_harness.h"
#include "particles/state_hash.h"
#include "particles/world.h"

namespace particles::cli {
namespace {

BallDef ball(Vec2 p, Vec2 v, double r) {
  BallDef b;
  b.position = p;
  b.velocity = v;
  b.radius = r;
  b.mass = 1.0;
  return b;
}

// Two equal balls meeting head-on at t = 1 s (e = 1, mu = 0, no spin, no
// gravity): nothing in it needs walls, forces, tangential work, spin or a grid.
SceneDef twoBalls() {
  SceneDef s;
  s.balls = {ball({0, 0}, {1, 0}, 0.5), ball({3, 0}, {-1, 0}, 0.5)};
  s.dt = 1e-3;
  s.duration = 2.0;
  return s;
}

// n smooth elastic balls at ~8 % area fraction in a square box, random
// directions at 1 m/s (fixed seed).
SceneDef gas(int n, double mu) {
  SceneDef s;
  s.contact = {1.0, mu};
  const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  const double spacing = 0.6, size = spacing * side + 0.4;
  s.walls = boxWalls({0, 0}, {size, size});
  std::uint64_t state = 5;
  for (int k = 0; k < n; ++k) {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    const double a = 2 * std::numbers::pi * static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
    s.balls.push_back(ball({0.5 + spacing * (k % side), 0.5 + spacing * (k / side)},
                           {std::cos(a), std::sin(a)}, 0.1));
  }
  s.dt = 1e-3;
  s.duration = 0.2;
  return s;
}

// ns per step of `scene` over `runs` fresh runs of its whole duration, and
// the final state's hash.
std::pair<double, std::uint64_t> time(const SceneDef& scene, int repeats, int runs) {
  std::uint64_t hash = 0;
  const double seconds = medianSeconds(repeats, [&](auto timed) {
    std::vector<World> worlds(static_cast<std::size_t>(runs), World(scene));
    timed([&] {
      for (World& w : worlds) w.run(scene.stepCount());
    });
    hash = stateHash(worlds.front());
  });
  return {1e9 * seconds / (static_cast<double>(runs) * static_cast<double>(scene.stepCount())),
          hash};
}

}  // namespace

std::vector<SkipRow> runSkipStudy(int repeats, bool full) {
  std::vector<SkipRow> rows;
  const int runs = full ? 200 : 50;

  // 1. The same two-ball scene with each unused stage switched on by a
  // change that cannot alter the motion.
  const SceneDef lean = twoBalls();
  SceneDef wall = lean, force = lean, grip = lean, grid = lean, all = lean;
  WallDef far;
  far.a = {-100, -100};
  far.b = {100, -100};  // 100 m below: never touched
  ForceDef zero;
  zero.type = ForceType::Constant;  // 0 N, 0 N m
  wall.walls = {far};
  force.forces = {zero};
  for (BallDef& b : grip.balls) b.friction = 0.5;  // head-on, no spin: no slip, lambda_t = 0
  grid.solver.gridThreshold = 0;
  all.walls = {far};
  all.forces = {zero};
  for (BallDef& b : all.balls) b.friction = 0.5;
  all.solver.gridThreshold = 0;
  const auto base = time(lean, repeats, runs);
  rows.push_back({"two-ball stages", "lean (every stage skipped)", 2, base.first, true});
  const std::pair<const char*, const SceneDef*> variants[] = {
      {"+ wall pass (a wall 100 m away)", &wall},
      {"+ force loop (a zero constant force)", &force},
      {"+ tangential and spin work (mu = 0.5, no slip to remove)", &grip},
      {"+ uniform grid (grid_threshold 0)", &grid},
      {"all stages on", &all}};
  for (const auto& [name, scene] : variants) {
    const auto t = time(*scene, repeats, runs);
    rows.push_back({"two-ball stages", name, 2, t.first, t.second == base.second});
  }

  // 2. Brute-force pairs against the grid, same scene, several N.
  std::vector<int> sizes{8, 16, 32, 64, 128, 256};
  if (full) sizes.push_back(1024);
  for (int n : sizes) {
    SceneDef brute = gas(n, 0.0), gridded = brute;
    brute.solver.gridThreshold = 1 << 30;
    gridded.solver.gridThreshold = 0;
    const int r = std::max(1, 4096 / n);
    const auto b = time(brute, repeats, r);
    const auto g = time(gridded, repeats, r);
    rows.push_back({"broad phase", "brute force", n, b.first, true});
    rows.push_back({"broad phase", "grid", n, g.first, g.second == b.second});
  }

  // 3. Angular work in a gas: mu = 0 skips it; mu = 0.3 does it (the
  // motion differs: the balls then spin, so sameResult is not expected).
  for (int n : {64, 256}) {
    const int r = std::max(1, 4096 / n);
    const auto smooth = time(gas(n, 0.0), repeats, r);
    const auto rough = time(gas(n, 0.3), repeats, r);
    rows.push_back({"angular work", "mu = 0 (no tangential or spin work)", n, smooth.first, true});
    rows.push_back({"angular work", "mu = 0.3 (different motion)", n, rough.first, false});
  }

  // 4. Continuous collision between balls (SolverSettings::sweptBalls) off
  // and on, brute force (16, 32) and grid (64, 256): what the sweep costs a
  // scene that has it on. Off is the step every other row measures; on, the
  // impacts happen at their time of impact, so the motion differs.
  for (int n : {16, 32, 64, 256}) {
    const int r = std::max(1, 4096 / n);
    SceneDef swept = gas(n, 0.0);
    swept.solver.sweptBalls = true;
    const auto off = time(gas(n, 0.0), repeats, r);
    const auto on = time(swept, repeats, r);
    rows.push_back({"swept balls", "off (discrete contacts)", n, off.first, true});
    rows.push_back({"swept balls", "on (different motion)", n, on.first, false});
  }
  return rows;
}

}  // namespace particles::cli
