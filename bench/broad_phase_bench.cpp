// Brute-force pairs against the uniform grid, for the ball count at which the
// World switches (SolverSettings::gridThreshold). The scene is a jittered
// grid of touching-or-nearly-touching balls, like a settled pile, where both
// finders return the same, realistic number of pairs.
//
//   build/bench/broad_phase_bench --benchmark_min_time=0.2
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "particles/broad_phase.h"

namespace {

struct Balls {
  std::vector<particles::Vec2> position;
  std::vector<double> radius;
};

Balls makePile(int n) {
  Balls balls;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  const int cols = static_cast<int>(std::ceil(std::sqrt(n)));
  for (int i = 0; i < n; ++i) {
    balls.position.emplace_back((i % cols) * 1.0 + jitter(rng), (i / cols) * 1.0 + jitter(rng));
    balls.radius.push_back(0.5);
  }
  return balls;
}

void BM_BruteForce(benchmark::State& state) {
  const Balls balls = makePile(static_cast<int>(state.range(0)));
  std::vector<particles::BallPair> pairs;
  for (auto _ : state) {
    particles::findPairsBruteForce(balls.position, balls.radius, pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs.size());
}

void BM_Grid(benchmark::State& state) {
  const Balls balls = makePile(static_cast<int>(state.range(0)));
  std::vector<particles::BallPair> pairs;
  particles::BroadPhase grid;
  for (auto _ : state) {
    grid.findPairs(balls.position, balls.radius, pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs.size());
}

}  // namespace

BENCHMARK(BM_BruteForce)->DenseRange(8, 64, 8)->Arg(96)->Arg(128)->Arg(256);
BENCHMARK(BM_Grid)->DenseRange(8, 64, 8)->Arg(96)->Arg(128)->Arg(256);
BENCHMARK_MAIN();
