// What `particles bench` measured, for its CSV, its summary and its HTML report.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bench_skip_study.h"
#include "particles/timestep/pareto.h"

namespace particles::cli {

// One configuration of one scene in one engine.
struct BenchRun {
  std::string scene;
  std::string engine;           // "engine" or "box2d"
  double dt = 0.0;              // s
  int contactPasses = 0;        // engine only (0 for Box2D)
  int velocityIterations = 0;   // Box2D only (0 for the engine)
  int positionIterations = 0;   // Box2D only
  long long steps = 0;          // steps per run
  double secondsPerSecond = 0;  // wall time per simulated second, median of repeats (s/s)
  double error = 0.0;           // the scene's metric, dimensionless (+inf: diverged)
  bool pareto = false;          // on its engine's Pareto front for this scene
};

struct BenchSceneSummary {
  std::string scene, kind, description;
  std::optional<timestep::EqualErrorRatio> ratio;
  double referenceConvergence = -1.0;  // ConvergedReference only (else < 0)
};

struct BenchResults {
  std::vector<BenchRun> runs;
  std::vector<BenchSceneSummary> scenes;
  std::vector<SkipRow> skip;
  int repeats = 0;
};

// "engine 3.2x faster than Box2D at error 1.0e-04" and the like.
std::string ratioText(const std::optional<timestep::EqualErrorRatio>& ratio);

}  // namespace particles::cli
