// particles bench --scale: the pile of issue 5 in the engine and in Box2D.
// Each run is timed step by step (the step alone: reading the state for the
// kinetic energy is outside the timer); figures are defined in docs/scale.md.
#include "bench_scale_command.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include "cli_common.h"
#include "commands.h"
#include "particles/pile/pile_metrics.h"
#include "particles/pile/pile_scene.h"
#include "particles/reference/box2d_world.h"
#include "particles/state_hash.h"
#include "particles/world.h"

namespace particles::cli {
namespace {

// The issue's two phases: falling (steps 0-299) and settled (300-599).
constexpr long long kPhaseSplit = 300;
constexpr long long kLastSteps = 60;  // kinetic energy window at the end

struct RunFigures {
  std::string engine;  // "engine", "soft" (the engine's soft step) or "box2d"
  std::uint64_t seed = 0;
  int count = 0;
  int threads = 1;
  int iterations = 0;  // velocity iterations per step (Box2D's: 8)
  long long steps = 0;
  double msFalling = NAN;  // ms/step over steps [0, 300)
  double msSettled = NAN;  // ms/step over steps [300, steps), NaN if none
  double diskStepsPerSecond = 0.0;
  // With --repeats R: the timings above are medians over the R runs, these
  // the slowest and fastest run's disk-steps/s.
  int repeats = 1;
  double diskStepsPerSecondMin = 0.0, diskStepsPerSecondMax = 0.0;
  std::uint64_t stateHash = 0;  // of the final state (particles/state_hash.h)
  pile::OverlapFigures overlap;
  double keLastMean = 0.0, keLastMax = 0.0, keFinal = 0.0;  // J
  double restEnergy = 0.0;                                  // J
  std::optional<long long> restStep;  // step (1-based) from which the pile stays at rest
  std::optional<double> bytesPerBall;
  long long outside = 0;  // balls with their centre outside the box at the end
  bool finite = true;
};

template <typename W>
RunFigures measure(W& world, const SceneDef& scene, long long steps) {
  using Clock = std::chrono::steady_clock;
  RunFigures f;
  f.count = static_cast<int>(scene.balls.size());
  f.steps = steps;
  std::vector<double> energy;
  energy.reserve(static_cast<std::size_t>(steps));
  double seconds[2] = {0.0, 0.0};
  // One buffer for the state read after every step: a fresh balls() copy
  // each step was, at a million balls, a fresh 48 MB mapping, 7.4 million page
  // faults and 50 s of system time in a 4.5-minute run (outside the timed step).
  std::vector<BallState> state(world.ballCount());
  for (long long s = 0; s < steps; ++s) {
    const Clock::time_point t0 = Clock::now();
    world.step();
    seconds[s < kPhaseSplit ? 0 : 1] += std::chrono::duration<double>(Clock::now() - t0).count();
    for (std::size_t i = 0; i < state.size(); ++i) state[i] = world.ball(i);
    energy.push_back(pile::kineticEnergy(state, scene.balls));
  }
  const long long falling = std::min(steps, kPhaseSplit), settled = steps - falling;
  f.msFalling = 1e3 * seconds[0] / static_cast<double>(falling);
  if (settled > 0) f.msSettled = 1e3 * seconds[1] / static_cast<double>(settled);
  f.diskStepsPerSecond =
      static_cast<double>(f.count) * static_cast<double>(steps) / (seconds[0] + seconds[1]);
  f.diskStepsPerSecondMin = f.diskStepsPerSecondMax = f.diskStepsPerSecond;
  const std::vector<BallState> end = world.balls();
  f.stateHash = stateHash(end);
  for (const BallState& b : end)
    f.finite = f.finite && b.position.allFinite() && b.velocity.allFinite();
  f.overlap = pile::measureOverlap(end, scene.balls);
  Vec2 lo = Vec2::Constant(INFINITY), hi = Vec2::Constant(-INFINITY);  // the box: its walls' ends
  for (const WallDef& w : scene.walls) {
    lo = lo.cwiseMin(w.a).cwiseMin(w.b);
    hi = hi.cwiseMax(w.a).cwiseMax(w.b);
  }
  f.outside = pile::countOutside(end, lo, hi);
  const std::size_t from = energy.size() - static_cast<std::size_t>(std::min(steps, kLastSteps));
  double sum = 0.0;
  for (std::size_t k = from; k < energy.size(); ++k) {
    sum += energy[k];
    f.keLastMax = std::max(f.keLastMax, energy[k]);
  }
  f.keLastMean = sum / static_cast<double>(energy.size() - from);
  f.keFinal = energy.back();
  f.restEnergy = pile::restEnergy(scene.balls);
  if (const auto r = pile::restStep(energy, f.restEnergy)) f.restStep = *r + 1;
  return f;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t h = v.size() / 2;
  return v.size() % 2 == 1 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

// The first of several runs of one configuration, with their timings as
// medians (each figure's own: the host's speed drifts within a run) and the
// spread of their disk-steps/s. Every other figure is the first run's: the
// runs ended in the same state (the caller checks the hashes).
RunFigures overRepeats(const std::vector<RunFigures>& runs) {
  RunFigures f = runs.front();
  std::vector<double> falling, settled, speed;
  for (const RunFigures& r : runs) {
    falling.push_back(r.msFalling);
    settled.push_back(r.msSettled);
    speed.push_back(r.diskStepsPerSecond);
  }
  f.repeats = static_cast<int>(runs.size());
  f.msFalling = median(falling);
  // NaN in every run (none of its steps past the falling phase), which the
  // sort must not see.
  if (!std::isnan(f.msSettled)) f.msSettled = median(settled);
  f.diskStepsPerSecond = median(speed);
  f.diskStepsPerSecondMin = *std::min_element(speed.begin(), speed.end());
  f.diskStepsPerSecondMax = *std::max_element(speed.begin(), speed.end());
  return f;
}

std::string fixed(double v, int digits) {
  if (std::isnan(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}
std::string general(double v) {
  if (std::isnan(v)) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

void printTable(const std::vector<RunFigures>& rows,
                const std::vector<std::optional<RunFigures>>& ref) {
  std::printf(
      "%-7s %8s %3s %3s %6s %10s %10s %10s %3s %13s %8s %8s %12s %6s %4s %7s %8s %8s %10s %16s\n",
      "engine", "N", "T", "K", "steps", "ms 0-299", "ms 300+", "Mdisk-st/s", "R", "min-max",
      "ovl max", "ovl mean", "KE last60", "rest", "out", "B/ball", "x Box2D", "ovl/B2D", "seed",
      "state hash");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const RunFigures& r = rows[i];
    const bool engine = r.engine != "box2d";
    double timeRatio = NAN, overlapRatio = NAN;
    if (engine && ref[i]) {
      timeRatio = r.diskStepsPerSecond / ref[i]->diskStepsPerSecond;
      overlapRatio = r.overlap.max / ref[i]->overlap.max;
    }
    const std::string spread = r.repeats > 1 ? fixed(r.diskStepsPerSecondMin / 1e6, 3) + "-" +
                                                   fixed(r.diskStepsPerSecondMax / 1e6, 3)
                                             : "-";
    std::printf(
        "%-7s %8d %3d %3d %6lld %10s %10s %10s %3d %13s %7s%% %7s%% %12s %6s %4lld %7s %8s %8s "
        "%10llu %16s\n",
        r.engine.c_str(), r.count, r.threads, r.iterations, r.steps, fixed(r.msFalling, 2).c_str(),
        fixed(r.msSettled, 2).c_str(), fixed(r.diskStepsPerSecond / 1e6, 3).c_str(), r.repeats,
        spread.c_str(), fixed(100.0 * r.overlap.max, 2).c_str(),
        fixed(100.0 * r.overlap.mean, 3).c_str(), general(r.keLastMean).c_str(),
        r.restStep ? std::to_string(*r.restStep).c_str() : "no", r.outside,
        r.bytesPerBall ? fixed(*r.bytesPerBall, 0).c_str() : "-", fixed(timeRatio, 2).c_str(),
        fixed(overlapRatio, 2).c_str(), static_cast<unsigned long long>(r.seed),
        hashHex(r.stateHash).c_str());
  }
  std::printf(
      "K: velocity iterations per step (soft: substeps); ms: mean wall time per step; R: runs "
      "(--repeats), ms and Mdisk-st/s their medians, min-max the slowest and fastest; KE last60: "
      "mean kinetic energy (J) over the last 60 steps; rest: the step from which KE stays <= "
      "M (%.2g m/s)^2 / 2 (\"no\": not at rest at the end); out: balls with their centre "
      "outside the box at the end; x Box2D: disk-steps/s engine / "
      "Box2D; ovl/B2D: max overlap engine / Box2D; state hash: FNV-1a of the final state, as "
      "'particles run --hash' (the same for every thread count)\n",
      pile::kRestSpeed);
}

// With several seeds, one line per engine, N and thread count over its
// seeds: one run of a pile that is still settling is one sample of a chaotic
// system, so its largest overlap and its energy are judged by their mean and
// their worst (docs/scale.md).
void printSeedSummary(const std::vector<RunFigures>& rows,
                      const std::vector<std::optional<RunFigures>>& ref, int seeds) {
  std::printf("\nover %d seeds:\n%-7s %8s %3s %3s %10s %9s %9s %9s %12s %7s %8s\n", seeds, "engine",
              "N", "T", "K", "Mdisk-st/s", "max mean", "max worst", "ovl mean", "KE last60",
              "at rest", "x Box2D");
  std::vector<bool> done(rows.size(), false);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (done[i]) continue;
    std::vector<double> speed, ratio;
    double maxSum = 0.0, maxWorst = 0.0, meanSum = 0.0, energySum = 0.0;
    int runs = 0, resting = 0;
    for (std::size_t j = i; j < rows.size(); ++j) {
      const RunFigures& r = rows[j];
      if (r.engine != rows[i].engine || r.count != rows[i].count || r.threads != rows[i].threads ||
          r.iterations != rows[i].iterations)
        continue;
      done[j] = true;
      ++runs;
      speed.push_back(r.diskStepsPerSecond);
      if (r.engine != "box2d" && ref[j])
        ratio.push_back(r.diskStepsPerSecond / ref[j]->diskStepsPerSecond);
      maxSum += r.overlap.max;
      maxWorst = std::max(maxWorst, r.overlap.max);
      meanSum += r.overlap.mean;
      energySum += r.keLastMean;
      if (r.restStep) ++resting;
    }
    const RunFigures& r = rows[i];
    std::printf("%-7s %8d %3d %3d %10s %8s%% %8s%% %8s%% %12s %4d/%-2d %8s\n", r.engine.c_str(),
                r.count, r.threads, r.iterations, fixed(median(speed) / 1e6, 3).c_str(),
                fixed(100.0 * maxSum / runs, 2).c_str(), fixed(100.0 * maxWorst, 2).c_str(),
                fixed(100.0 * meanSum / runs, 3).c_str(), general(energySum / runs).c_str(),
                resting, runs, ratio.empty() ? "-" : fixed(median(ratio), 2).c_str());
  }
  std::printf(
      "Mdisk-st/s and x Box2D: medians over the seeds (x Box2D of each seed's own Box2D run); "
      "max mean / max worst: mean and largest of the runs' max overlaps; ovl mean and KE "
      "last60: means over the seeds; at rest: runs at rest at the end\n");
}

// The engine promises the same bits whatever the thread count
// (docs/determinism.md): runs that differ in it alone must end in the same
// state. Says which did not, on stderr.
bool sameStateForEveryThreadCount(const std::vector<RunFigures>& rows) {
  bool same = true;
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = i + 1; j < rows.size(); ++j) {
      const RunFigures &a = rows[i], &b = rows[j];
      if (a.engine == "box2d" || a.engine != b.engine || a.count != b.count || a.seed != b.seed ||
          a.iterations != b.iterations || a.stateHash == b.stateHash)
        continue;
      printError("bench: " + a.engine + " N=" + std::to_string(a.count) +
                 " K=" + std::to_string(a.iterations) + " seed " + std::to_string(a.seed) +
                 ": T=" + std::to_string(a.threads) + " and T=" + std::to_string(b.threads) +
                 " ended in different states (hashes " + hashHex(a.stateHash) + " and " +
                 hashHex(b.stateHash) + "): the engine is not deterministic");
      same = false;
    }
  return same;
}

void writeCsv(std::ostream& out, const std::vector<RunFigures>& rows,
              const std::vector<std::optional<RunFigures>>& ref, bool poly) {
  out << "engine,n,polydisperse,threads,velocity_iterations,steps,"
         "ms_per_step_0_299,ms_per_step_300_599,"
         "disk_steps_per_s,overlap_max_fraction,overlap_mean_fraction,touching_pairs,"
         "ke_last60_mean_J,ke_last60_max_J,ke_final_J,rest_energy_J,rest_step,bytes_per_ball,"
         "speed_ratio_engine_over_box2d,overlap_max_ratio_engine_over_box2d,balls_outside_box,"
         "seed,repeats,disk_steps_per_s_min,disk_steps_per_s_max,state_hash\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const RunFigures& r = rows[i];
    const bool withRef = r.engine != "box2d" && ref[i].has_value();
    out << r.engine << ',' << r.count << ',' << (poly ? 1 : 0) << ',' << r.threads << ','
        << r.iterations << ',' << r.steps << ',' << general(r.msFalling) << ','
        << general(r.msSettled) << ',' << general(r.diskStepsPerSecond) << ','
        << general(r.overlap.max) << ',' << general(r.overlap.mean) << ','
        << r.overlap.touchingPairs << ',' << general(r.keLastMean) << ',' << general(r.keLastMax)
        << ',' << general(r.keFinal) << ',' << general(r.restEnergy) << ','
        << (r.restStep ? std::to_string(*r.restStep) : "") << ','
        << (r.bytesPerBall ? general(*r.bytesPerBall) : "") << ','
        << (withRef ? general(r.diskStepsPerSecond / ref[i]->diskStepsPerSecond) : "") << ','
        << (withRef ? general(r.overlap.max / ref[i]->overlap.max) : "") << ',' << r.outside << ','
        << r.seed << ',' << r.repeats << ',' << general(r.diskStepsPerSecondMin) << ','
        << general(r.diskStepsPerSecondMax) << ',' << hashHex(r.stateHash) << '\n';
  }
}

}  // namespace

void addScaleBenchOptions(CLI::App& bench, ScaleBenchOptions& o) {
  bench.add_flag("--scale", o.scale,
                 "The pile benchmark (issue 5): N disks dropped into a box, engine and Box2D");
  bench.add_option("--n", o.counts, "Disk counts N, one run each (default 1000 10000)")
      ->type_name("N...")
      ->expected(1, 64)
      ->check(integerInRange(1, 10000000));
  bench
      .add_option("--threads", o.threads,
                  "Engine thread counts, one engine run each (default 1); Box2D runs once per N, "
                  "on one thread")
      ->type_name("T...")
      ->expected(1, 16)
      ->check(integerInRange(1, 64));
  bench.add_flag("--poly", o.polydisperse, "Polydisperse disks: radius uniform in [0.4, 0.6] m");
  bench.add_option("--steps", o.steps, "Steps of 1/60 s per run (default 600)")
      ->type_name("S")
      ->check(integerInRange(1, 1000000));
  bench.add_flag("--no-box2d", o.noBox2D, "Engine only, no Box2D run");
  // --csv FILE is registered once for both benchmarks (bench_command.cpp);
  // with --scale it names this CSV (default pile.csv; '' = none).
  CLI::Option* iterations =
      bench
          .add_option(
              "--iterations", o.iterations,
              "Engine velocity iterations per step on the large-scene path, one engine run "
              "per value and thread count (default: SolverSettings::scaleVelocityIterations, "
              "8): run time against error in one run, against one Box2D run per N")
          ->type_name("K...")
          ->expected(1, 16)
          ->check(integerInRange(1, 10000));
  bench
      .add_option("--position-passes", o.positionPasses,
                  "Engine overlap-removal passes per step on the large-scene path (default: "
                  "SolverSettings::scalePositionPasses, 2)")
      ->type_name("P")
      ->check(integerInRange(1, 10000));
  bench
      .add_option("--fast-pair-cells", o.fastPairCells,
                  "Grid cells the engine's pair search reaches for a fast ball on the large-scene "
                  "path, 0 (off) to 7 (default: SolverSettings::scaleFastPairCells, 2)")
      ->type_name("C")
      ->check(integerInRange(0, 7));
  bench
      .add_option("--band-rows", o.bandRows,
                  "Height in grid rows of the bands of the engine's Gauss-Seidel order on the "
                  "large-scene path at any N, 0 (whole strips) to 1000 (default: "
                  "SolverSettings::scaleBandRows, 2, from SolverSettings::scaleBandsFrom, "
                  "50,000 disks)")
      ->type_name("B")
      ->check(integerInRange(0, 1000));
  bench
      .add_option("--relaxation", o.relaxation,
                  "Engine over-relaxation of the normal impulses on the large-scene path, 1 "
                  "(off) to 1.99 (default: SolverSettings::scaleOverRelaxation, 1.8)")
      ->type_name("W")
      ->check(finiteInRange(1.0, 1.99));
  bench
      .add_option("--shock", o.shock,
                  "Engine shock propagation in the overlap removal, 0..1 (default: "
                  "SolverSettings::scaleShockPropagation, 0: share by inverse mass)")
      ->type_name("K")
      ->check(finiteInRange(0.0, 1.0));
  bench.add_flag("--no-velocity-shock", o.noVelocityShock,
                 "Engine without shock propagation in velocities (SolverSettings::"
                 "scaleVelocityShock, on by default)");
  bench.add_flag("--no-settle-iteration", o.noSettleIteration,
                 "Engine without the settle iteration once a pile has settled "
                 "(SolverSettings::scaleSettleIteration, on by default)");
  bench.add_flag("--sequential-impacts", o.sequentialImpacts,
                 "Engine with the impacts of a step in sequence where the passes would share "
                 "them (SolverSettings::scaleSequentialImpacts, off by default)");
  bench.add_flag("--no-wavefront", o.noWavefront,
                 "Engine with its velocity passes (the soft step's: each substep's passes) one "
                 "after another instead of as a wavefront over the bands "
                 "(SolverSettings::scaleWavefront; the same bits)");
  bench
      .add_option("--substeps", o.substeps,
                  "Engine with the soft step on the large-scene path, S substeps a step, 1 to 64 "
                  "(SolverSettings::scaleSubsteps; default 0: the rigid step); its rows say "
                  "\"soft\" and K is S")
      ->type_name("S")
      ->check(integerInRange(1, 64))
      ->excludes(iterations);
  bench
      .add_option("--contact-hertz", o.contactHertz,
                  "Stiffness of the soft step's contacts, Hz, 1 to 10000, at most a quarter of "
                  "the substep rate (SolverSettings::scaleContactHertz; default: that most)")
      ->type_name("HZ")
      ->check(finiteInRange(1.0, 10000.0));
  bench.add_option("--seed", o.seed, "Seed of the grid's jitter and radii (default 20261201)")
      ->type_name("SEED")
      ->check(unsigned64());
  bench
      .add_option("--seeds", o.seeds,
                  "Runs per N with seeds SEED, SEED+1, ... (default 1); with more than one, a "
                  "summary over the seeds follows the table")
      ->type_name("K")
      ->check(integerInRange(1, 1000));
}

int runScaleBench(const ScaleBenchOptions& o) {
  std::ofstream csv;
  if (!o.csv.empty()) {
    csv.open(o.csv, std::ios::binary | std::ios::trunc);
    if (!csv) {
      printError("--csv: cannot open '" + o.csv + "' for writing");
      return kExitBadInput;
    }
  }
  std::vector<RunFigures> rows;
  std::vector<std::optional<RunFigures>> ref;  // the Box2D run of each row's N
  bool stopped = false;                        // an engine run threw StepError
  bool diverged = false;                       // runs that must end in the same state did not
  const std::vector<int> iterations =
      o.iterations.empty() ? std::vector<int>{SolverSettings{}.scaleVelocityIterations}
                           : o.iterations;
  for (const int n : o.counts) {
    for (int k = 0; k < o.seeds; ++k) {
      pile::PileParams params;
      params.count = n;
      params.polydisperse = o.polydisperse;
      params.seed = o.seed + static_cast<std::uint64_t>(k);
      std::optional<RunFigures> box2d;
      if (!o.noBox2D) {
        const SceneDef scene = pile::makePile(params);
        reference::Box2DSettings settings = reference::Box2DSettings::forScene(scene);
        settings.velocityIterations = 8;
        settings.positionIterations = 3;
        reference::Box2DWorld world(scene, settings);
        box2d = measure(world, scene, o.steps);
        box2d->engine = "box2d";
        box2d->seed = params.seed;
        box2d->iterations = settings.velocityIterations;
        std::fprintf(stderr, "particles: bench: box2d N=%d seed %llu done\n", n,
                     static_cast<unsigned long long>(params.seed));
      }
      for (const int t : o.threads)
        for (const int k : iterations) {
          params.threads = t;
          SceneDef scene = pile::makePile(params);
          scene.solver.scaleVelocityIterations = k;
          if (o.positionPasses > 0) scene.solver.scalePositionPasses = o.positionPasses;
          if (o.fastPairCells >= 0) scene.solver.scaleFastPairCells = o.fastPairCells;
          if (o.bandRows >= 0) {
            // Asked for: at any N, not only from SolverSettings::scaleBandsFrom.
            scene.solver.scaleBandRows = o.bandRows;
            scene.solver.scaleBandsFrom = 0;
          }
          if (o.shock >= 0.0) scene.solver.scaleShockPropagation = o.shock;
          if (o.relaxation > 0.0) scene.solver.scaleOverRelaxation = o.relaxation;
          if (o.noVelocityShock) scene.solver.scaleVelocityShock = false;
          if (o.noSettleIteration) scene.solver.scaleSettleIteration = false;
          if (o.noWavefront) scene.solver.scaleWavefront = false;
          if (o.sequentialImpacts) scene.solver.scaleSequentialImpacts = true;
          if (o.substeps > 0) scene.solver.scaleSubsteps = o.substeps;
          if (o.contactHertz > 0.0) scene.solver.scaleContactHertz = o.contactHertz;
          const std::string name = o.substeps > 0 ? "soft" : "engine";
          const std::string run = name + " N=" + std::to_string(n) + " T=" + std::to_string(t) +
                                  " K=" + std::to_string(o.substeps > 0 ? o.substeps : k) +
                                  " seed " + std::to_string(params.seed);
          std::vector<RunFigures> runs;
          try {
            for (int r = 0; r < std::max(1, o.repeats); ++r) {
              World world(scene);  // a fresh world each time: construction is not timed
              RunFigures f = measure(world, scene, o.steps);
              f.bytesPerBall = static_cast<double>(world.memoryBytes()) / n;
              runs.push_back(f);
            }
          } catch (const StepError& e) {
            // This run blew up (docs/scale.md, "A state that cannot be
            // stepped"): the others still make the table and the CSV.
            printError("bench: " + run + ": " + e.what());
            stopped = true;
            continue;
          }
          for (const RunFigures& again : runs)
            if (again.stateHash != runs.front().stateHash) {
              printError("bench: " + run + ": its runs ended in different states (hashes " +
                         hashHex(runs.front().stateHash) + " and " + hashHex(again.stateHash) +
                         "): the engine is not deterministic");
              diverged = true;
              break;
            }
          RunFigures f = overRepeats(runs);
          f.engine = name;
          f.seed = params.seed;
          f.threads = t;
          f.iterations = o.substeps > 0 ? o.substeps : k;
          std::fprintf(stderr, "particles: bench: %s done\n", run.c_str());
          rows.push_back(f);
          ref.push_back(box2d);
        }
      if (box2d) {
        rows.push_back(*box2d);
        ref.push_back(box2d);
      }
    }
  }
  printTable(rows, ref);
  if (o.seeds > 1) printSeedSummary(rows, ref, o.seeds);
  if (!sameStateForEveryThreadCount(rows)) diverged = true;
  bool finite = true;
  for (const RunFigures& r : rows) finite = finite && r.finite;
  if (csv.is_open()) {
    writeCsv(csv, rows, ref, o.polydisperse);
    csv.close();
    if (!csv) {
      printError("--csv: error writing '" + o.csv + "'");
      return kExitFailed;
    }
  }
  if (!finite) {
    printError("bench: a run diverged (non-finite state)");
    return kExitFailed;
  }
  return stopped || diverged ? kExitFailed : kExitOk;
}

}  // namespace particles::cli
