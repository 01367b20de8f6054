// `particles bench --scale`: the "pile" scene of issue 5 at N disks, run in
// the engine (for each thread count) and in its Box2D twin in the same run;
// prints a table and writes CSV (docs/cli.md, docs/scale.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace particles::cli {

struct ScaleBenchOptions {
  bool scale = false;                    // --scale: run this benchmark
  std::vector<int> counts{1000, 10000};  // --n: disk counts N
  std::vector<int> threads{1};           // --threads: engine thread counts
  bool polydisperse = false;             // --poly: radius uniform in [0.4, 0.6] m
  long long steps = 600;                 // --steps: steps of 1/60 s per run
  bool noBox2D = false;                  // --no-box2d: engine only
  std::string csv = "pile.csv";          // --csv: where the CSV goes ("" = none)
  std::uint64_t seed = 20261201;         // --seed: the grid's jitter and radii
  int seeds = 1;  // --seeds: runs per N with seeds seed, seed + 1, ... (a settling pile is chaotic)
  // --iterations: SolverSettings::scaleVelocityIterations, one engine run per
  // value and thread count (empty = the default)
  std::vector<int> iterations;
  int positionPasses = 0;   // --position-passes: SolverSettings::scalePositionPasses (0 = default)
  int fastPairCells = -1;   // --fast-pair-cells: SolverSettings::scaleFastPairCells (< 0 = default)
  int bandRows = -1;        // --band-rows: SolverSettings::scaleBandRows (< 0 = default)
  double shock = -1.0;      // --shock: SolverSettings::scaleShockPropagation (< 0 = default)
  double relaxation = 0.0;  // --relaxation: SolverSettings::scaleOverRelaxation (0 = default)
  bool noVelocityShock = false;  // --no-velocity-shock: SolverSettings::scaleVelocityShock off
  // --no-settle-iteration: SolverSettings::scaleSettleIteration off
  bool noSettleIteration = false;
  // --sequential-impacts: SolverSettings::scaleSequentialImpacts on
  bool sequentialImpacts = false;
  // --no-wavefront: SolverSettings::scaleWavefront off (same bits, whole passes)
  bool noWavefront = false;
  // --substeps: SolverSettings::scaleSubsteps, the soft step (0 = the rigid step, the default)
  int substeps = 0;
  double contactHertz = 0.0;  // --contact-hertz: SolverSettings::scaleContactHertz (0 = default)
  // --repeats (shared with the catalogue benchmark, whose default is 3): runs
  // of each engine configuration; its timings are their medians
  int repeats = 1;
};

// Registers the options above on the `bench` subcommand.
void addScaleBenchOptions(CLI::App& bench, ScaleBenchOptions& options);

// Runs the benchmark; returns the exit status (0, 1 on a non-finite state or
// an I/O error, 2 when the CSV file cannot be opened).
int runScaleBench(const ScaleBenchOptions& options);

}  // namespace particles::cli
