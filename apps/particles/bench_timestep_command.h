// `particles bench`, run time against error (docs/bench.md): the sweep of
// the time-stepped catalogue in both engines, the Pareto fronts, the speed
// ratio at equal error, and the skip study.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace particles::cli {

struct TimestepBenchOptions {
  int repeats = 3;                  // timed runs per configuration; the median counts
  bool full = false;                // the wider sweep (more dt, passes and iterations)
  std::vector<std::string> scenes;  // catalogue names; empty = all
  std::string csv = "bench.csv";    // the sweep, one row per configuration
  std::string skipCsv = "bench_skip.csv";
  std::string report;  // DIR for index.html; empty = none
  bool noSkipStudy = false;
};

void addTimestepBenchOptions(CLI::App& bench, TimestepBenchOptions& options);
int runTimestepBench(const TimestepBenchOptions& options);

}  // namespace particles::cli
