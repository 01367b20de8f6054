#include "bench_timestep_command.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "bench_harness.h"
#include "bench_report.h"
#include "bench_results.h"
#include "cli_common.h"
#include "commands.h"
#include "csv_field.h"
#include "particles/reference/box2d_settings.h"
#include "particles/scene_output.h"
#include "particles/timestep/catalogue.h"
#include "suite_output.h"

namespace particles::cli {
namespace {

using timestep::TimestepScene;

struct Sweep {
  std::vector<double> dtFactors;                // times the scene's base dt
  std::vector<int> passes;                      // engine contact passes
  std::vector<std::pair<int, int>> iterations;  // Box2D (velocity, position)
};

Sweep sweepFor(bool full) {
  if (full)
    return {{8, 4, 2, 1, 0.5, 0.25, 0.125},
            {64, 16, 4, 1},
            {{8, 3}, {2, 1}, {3, 1}, {20, 8}, {50, 20}}};
  return {{2, 1, 0.5, 0.25}, {64, 4}, {{8, 3}, {3, 1}, {20, 8}}};
}

// Times `repeats` runs of fresh steppers (construction not timed), then one
// more run under the metric for the error (the metric's own cost is not timed).
template <typename Make>
void measureRun(BenchRun& run, const SceneDef& scene, const TimestepScene& t,
                const std::vector<double>& reference, int repeats, Make make) {
  run.steps = scene.stepCount();
  const double seconds = medianSeconds(repeats, [&](auto timed) {
    auto stepper = make();
    timed([&] {
      for (long long k = 0; k < run.steps; ++k) stepper->step();
    });
  });
  run.secondsPerSecond = seconds / (static_cast<double>(run.steps) * scene.dt);
  auto stepper = make();
  auto metric = t.metric(reference);
  run.error = timestep::measure(*stepper, *metric, run.steps);
}

std::string sci(double x, int digits = 2) {
  if (std::isinf(x)) return "inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*e", digits, x);
  return buf;
}

void writeCsv(const std::string& path, const std::vector<BenchRun>& runs) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "scene,engine,dt_s,contact_passes,velocity_iterations,position_iterations,steps,"
         "wall_s_per_simulated_s,error,pareto\n";
  for (const BenchRun& r : runs) {
    const bool engine = r.engine == "engine";
    out << csvField(r.scene) << ',' << r.engine << ',' << formatDouble(r.dt) << ','
        << (engine ? std::to_string(r.contactPasses) : "") << ','
        << (engine ? "" : std::to_string(r.velocityIterations)) << ','
        << (engine ? "" : std::to_string(r.positionIterations)) << ',' << r.steps << ','
        << formatDouble(r.secondsPerSecond) << ','
        << (std::isfinite(r.error) ? formatDouble(r.error) : "inf") << ',' << (r.pareto ? 1 : 0)
        << '\n';
  }
  if (!out) throw std::runtime_error("error writing " + path);
}

void writeSkipCsv(const std::string& path, const std::vector<SkipRow>& rows) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "study,variant,balls,ns_per_step,same_result\n";
  for (const SkipRow& r : rows)
    out << csvField(r.study) << ',' << csvField(r.variant) << ',' << r.balls << ','
        << formatDouble(r.nsPerStep) << ',' << (r.sameResult ? 1 : 0) << '\n';
  if (!out) throw std::runtime_error("error writing " + path);
}

std::string summaryText(const BenchResults& results) {
  std::ostringstream out;
  out << "scene          metric               best engine error   best Box2D error   at equal "
         "error\n";
  for (const BenchSceneSummary& s : results.scenes) {
    double be = INFINITY, bb = INFINITY;
    for (const BenchRun& r : results.runs) {
      if (r.scene != s.scene) continue;
      (r.engine == "engine" ? be : bb) = std::min(r.engine == "engine" ? be : bb, r.error);
    }
    char line[256];
    std::snprintf(line, sizeof line, "%-14s %-20s %-19s %-18s ", s.scene.c_str(), s.kind.c_str(),
                  sci(be).c_str(), sci(bb).c_str());
    out << line << ratioText(s.ratio);
    if (s.referenceConvergence >= 0)
      out << " (reference converged to " << sci(s.referenceConvergence) << ")";
    out << '\n';
  }
  if (!results.skip.empty()) {
    out << "\nSkip study (ns per step, median of " << results.repeats << "):\n";
    for (const SkipRow& r : results.skip) {
      char line[256];
      std::snprintf(line, sizeof line, "  %-16s %4d balls  %-58s %10.1f ns%s\n", r.study.c_str(),
                    r.balls, r.variant.c_str(), r.nsPerStep,
                    r.sameResult ? "" : "  (result differs)");
      out << line;
    }
  }
  return out.str();
}

}  // namespace

std::string ratioText(const std::optional<timestep::EqualErrorRatio>& r) {
  if (!r) return "no common error";
  const bool engineFaster = r->ratio >= 1.0;
  const double factor = engineFaster ? r->ratio : 1.0 / r->ratio;
  // A clamped time was the cheapest run of a front that never was that
  // inaccurate: the true time there is at most that, so the ratio is a bound
  // in favour of that engine.
  const bool bound = engineFaster ? r->engineClamped : r->box2dClamped;
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s %s%.3gx faster than %s at error %s",
                engineFaster ? "engine" : "Box2D", bound ? ">= " : "", factor,
                engineFaster ? "Box2D" : "engine", sci(r->error).c_str());
  return buf;
}

void addTimestepBenchOptions(CLI::App& bench, TimestepBenchOptions& o) {
  bench
      .add_option("--repeats", o.repeats,
                  "Timed runs per configuration (the median counts), 1 to 1000; with --scale, "
                  "runs of each engine configuration (default 1), which must end in the same "
                  "state")
      ->type_name("N")
      ->default_val(o.repeats)
      ->check(integerInRange(1, 1000));
  bench.add_flag(
      "--full", o.full,
      "Wider sweep: dt x 8 .. x 1/8, contact passes 64/16/4/1, five Box2D iteration pairs");
  bench
      .add_option("--scene", o.scenes,
                  "Only these catalogue scenes (repeatable): bounce, slide_roll, incline_roll, "
                  "oblique_spin, pull, cradle, billiards, pile, gas")
      ->type_name("NAME")
      ->check(CLI::IsMember({"bounce", "slide_roll", "incline_roll", "oblique_spin", "pull",
                             "cradle", "billiards", "pile", "gas"}));
  bench
      .add_option("--csv", o.csv,
                  "The sweep as CSV, one row per configuration (with --scale: the pile's figures, "
                  "default pile.csv)")
      ->type_name("FILE")
      ->default_val(o.csv);
  bench.add_option("--skip-csv", o.skipCsv, "The skip study as CSV")
      ->type_name("FILE")
      ->default_val(o.skipCsv);
  bench
      .add_option("--report", o.report,
                  "Also write DIR/index.html (tables and runtime-vs-error plots) with both CSVs")
      ->type_name("DIR");
  bench.add_flag("--no-skip-study", o.noSkipStudy, "Leave out the skip study");
}

int runTimestepBench(const TimestepBenchOptions& o) {
  if (!o.report.empty() && !prepareReportDir(o.report)) return kExitBadInput;
  const Sweep sweep = sweepFor(o.full);
  BenchResults results;
  results.repeats = o.repeats;
  for (const TimestepScene& t : timestep::catalogue()) {
    if (!o.scenes.empty() && std::find(o.scenes.begin(), o.scenes.end(), t.name) == o.scenes.end())
      continue;
    std::cerr << "bench: " << t.name << "..." << std::endl;
    BenchSceneSummary summary{t.name, timestep::metricKindName(t.kind), t.description, {}, -1.0};
    std::vector<double> reference;
    if (t.kind == timestep::MetricKind::ConvergedReference) {
      const timestep::Reference ref = timestep::computeReference(t);
      reference = ref.values;
      summary.referenceConvergence = ref.convergence;
    }
    const std::size_t first = results.runs.size();
    for (double f : sweep.dtFactors) {
      const SceneDef scene = timestep::withStep(t.scene, t.scene.dt * f);
      for (int passes : sweep.passes) {
        SceneDef s = scene;
        s.solver.contactPasses = passes;
        BenchRun run{t.name, "engine", s.dt, passes, 0, 0, 0, 0, 0, false};
        measureRun(run, s, t, reference, o.repeats, [&] { return timestep::engineStepper(s); });
        results.runs.push_back(run);
      }
      for (const auto& [vel, pos] : sweep.iterations) {
        reference::Box2DSettings settings = reference::Box2DSettings::forScene(scene);
        settings.velocityIterations = vel;
        settings.positionIterations = pos;
        BenchRun run{t.name, "box2d", scene.dt, 0, vel, pos, 0, 0, 0, false};
        measureRun(run, scene, t, reference, o.repeats,
                   [&] { return timestep::box2dStepper(scene, settings); });
        results.runs.push_back(run);
      }
    }
    std::vector<timestep::CostPoint> pe, pb;
    for (std::size_t i = first; i < results.runs.size(); ++i) {
      const BenchRun& r = results.runs[i];
      // Against a converged reference, errors below the reference's own
      // uncertainty cannot be told apart: they count as that uncertainty.
      const double error = std::max(r.error, summary.referenceConvergence);
      (r.engine == "engine" ? pe : pb).push_back({r.secondsPerSecond, error, i});
    }
    const auto fe = timestep::paretoFront(pe), fb = timestep::paretoFront(pb);
    for (const auto& p : fe) results.runs[p.index].pareto = true;
    for (const auto& p : fb) results.runs[p.index].pareto = true;
    summary.ratio = timestep::equalErrorRatio(fe, fb);
    results.scenes.push_back(summary);
  }
  if (!o.noSkipStudy) {
    std::cerr << "bench: skip study..." << std::endl;
    results.skip = runSkipStudy(o.repeats, o.full);
  }

  try {
    writeCsv(o.csv, results.runs);
    if (!o.noSkipStudy) writeSkipCsv(o.skipCsv, results.skip);
    if (!o.report.empty()) {
      namespace fs = std::filesystem;
      writeCsv((fs::path(o.report) / "bench.csv").string(), results.runs);
      if (!o.noSkipStudy)
        writeSkipCsv((fs::path(o.report) / "bench_skip.csv").string(), results.skip);
      writeBenchReport(o.report, results);
    }
  } catch (const std::exception& e) {
    printError(e.what());
    return kExitFailed;
  }
  std::cout << summaryText(results) << "CSV: " << o.csv
            << (o.noSkipStudy ? "" : " and " + o.skipCsv)
            << (o.report.empty() ? "" : "; report: " + o.report + "/index.html") << '\n';
  return std::cout ? kExitOk : kExitFailed;
}

}  // namespace particles::cli
