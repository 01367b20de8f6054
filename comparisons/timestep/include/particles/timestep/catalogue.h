// The catalogue of time-stepped scenes with known answers (docs/bench.md):
// each is a SceneDef, built once, that both the engine and its Box2D twin
// run, plus the metric that says how wrong a run of it was.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "particles/scene.h"
#include "particles/timestep/metrics.h"

namespace particles::timestep {

struct TimestepScene {
  std::string name;         // short id: bounce, slide_roll, ...
  std::string description;  // one line, with the expected answer
  MetricKind kind = MetricKind::Analytic;
  SceneDef scene;  // dt = the bench's base step (s), duration = the simulated time (s)
  // ConvergedReference only: the reference runs the engine at this dt (s); its
  // convergence is shown by a second run at twice this dt.
  double referenceDt = 0.0;
  // The observable the reference is compared on (ConvergedReference only).
  Observable observable;
  double referenceScale = 1.0;  // divides observable differences (its unit)
  // The metric for one run. `reference` is the reference run's observable
  // (ConvergedReference only; empty otherwise).
  std::function<std::unique_ptr<Metric>(const std::vector<double>& reference)> metric;
};

// All scenes, in a fixed order: bounce, slide_roll, incline_roll,
// oblique_spin, pull, cradle, billiards, pile, gas.
std::vector<TimestepScene> catalogue();
// One scene by name; throws std::out_of_range for an unknown name.
TimestepScene catalogueScene(const std::string& name);

// The same scene with another dt and the same simulated duration.
SceneDef withStep(const SceneDef& scene, double dt);

// The reference of a ConvergedReference scene: the observable of the engine
// run at referenceDt, and how far the run at 2 referenceDt is from it (in
// units of referenceScale): the reference's own uncertainty.
struct Reference {
  std::vector<double> values;
  double convergence = 0.0;  // dimensionless, |o(2 dt_ref) - o(dt_ref)| / scale
};
Reference computeReference(const TimestepScene& scene);

}  // namespace particles::timestep
