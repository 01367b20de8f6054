// What skipping unused stages buys (World::plan(), docs/bench.md "Skip
// study"): the same scene timed with and without stages it does not need.
#pragma once

#include <string>
#include <vector>

namespace particles::cli {

struct SkipRow {
  std::string study;    // "two-ball stages", "broad phase", "angular work", "swept balls"
  std::string variant;  // what this run had switched on
  int balls = 0;
  double nsPerStep = 0.0;  // ns of wall time per step, median of repeats
  // The final state is bit-identical to the study's first (lean) variant:
  // the extra stages cost time only. (False where the physics differ on
  // purpose, said in `variant`.)
  bool sameResult = true;
};

std::vector<SkipRow> runSkipStudy(int repeats, bool full);

}  // namespace particles::cli
