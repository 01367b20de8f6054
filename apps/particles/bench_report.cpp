#include "bench_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "particles/html/document.h"

namespace particles::cli {
namespace {

std::string sci(double x) {
  if (!std::isfinite(x)) return "inf (diverged)";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2e", x);
  return buf;
}

std::string config(const BenchRun& r) {
  char buf[96];
  if (r.engine == "engine")
    std::snprintf(buf, sizeof buf, "dt %.3g s, %d passes", r.dt, r.contactPasses);
  else
    std::snprintf(buf, sizeof buf, "dt %.3g s, %d/%d iterations", r.dt, r.velocityIterations,
                  r.positionIterations);
  return buf;
}

html::Plot scenePlot(const std::string& scene, const std::vector<BenchRun>& runs) {
  html::Plot p;
  p.title = scene + ": wall time per simulated second against error";
  p.xLabel = "error (dimensionless; exact answers drawn at 1e-16)";
  p.yLabel = "wall s per simulated s";
  p.logX = p.logY = true;
  const char* engines[] = {"engine", "box2d"};
  for (int k = 0; k < 2; ++k) {
    html::Series all{
        std::string(k == 0 ? "engine" : "Box2D") + ", every run", {}, "points", k == 0 ? 6 : 4, k};
    html::Series front{std::string(k == 0 ? "engine" : "Box2D") + ", Pareto front",
                       {},
                       "linespoints",
                       k == 0 ? 7 : 5,
                       k};
    std::vector<std::pair<double, double>> f;
    for (const BenchRun& r : runs) {
      if (r.scene != scene || r.engine != engines[k] || !std::isfinite(r.error)) continue;
      const std::pair<double, double> pt{std::max(r.error, timestep::kErrorFloor),
                                         r.secondsPerSecond};
      all.points.push_back(pt);
      if (r.pareto) f.push_back(pt);
    }
    std::sort(f.begin(), f.end());
    front.points = f;
    p.series.push_back(all);
    p.series.push_back(front);
  }
  return p;
}

}  // namespace

void writeBenchReport(const std::string& dir, const BenchResults& results) {
  html::Document doc("particles bench: run time against error");
  doc.paragraph(
      "Each scene of the time-stepped catalogue (docs/bench.md) run in the engine and in its "
      "Box2D 2.4.1 twin over a sweep of time steps, engine contact passes and Box2D "
      "velocity/position iterations. Wall time is the median of " +
      std::to_string(results.repeats) +
      " runs per configuration, per simulated second. Errors are dimensionless (the scale of "
      "each metric is in docs/bench.md). The same data is in bench.csv.");
  doc.note(
      "Timings depend on the machine and its load; compare the two engines within one run, "
      "not across runs.");

  html::Table summary{"Per scene: at equal error",
                      {"scene", "metric", "expected", "best engine error", "best Box2D error",
                       "speed at equal error"},
                      {},
                      {}};
  for (const BenchSceneSummary& s : results.scenes) {
    double be = INFINITY, bb = INFINITY;
    for (const BenchRun& r : results.runs)
      if (r.scene == s.scene)
        (r.engine == "engine" ? be : bb) = std::min(r.engine == "engine" ? be : bb, r.error);
    std::string kind = s.kind;
    if (s.referenceConvergence >= 0) kind += " (converged to " + sci(s.referenceConvergence) + ")";
    summary.rows.push_back({s.scene, kind, s.description, sci(be), sci(bb), ratioText(s.ratio)});
  }
  doc.table(summary);

  for (const BenchSceneSummary& s : results.scenes) {
    doc.heading(s.scene);
    doc.paragraph(s.description + ". " + ratioText(s.ratio) + ".");
    if (s.referenceConvergence >= 0)
      doc.note("The reference (the engine at a far smaller step) is itself uncertain by " +
               sci(s.referenceConvergence) +
               ": errors below that cannot be told apart and count as that for the fronts, "
               "so the plot shows runs left of it that are not on a front.");
    doc.plot(scenePlot(s.scene, results.runs));
    html::Table front{"Pareto fronts (cheapest first)",
                      {"engine", "configuration", "wall s / s", "error"},
                      {},
                      {}};
    std::vector<BenchRun> rows;
    for (const BenchRun& r : results.runs)
      if (r.scene == s.scene && r.pareto) rows.push_back(r);
    std::sort(rows.begin(), rows.end(), [](const BenchRun& a, const BenchRun& b) {
      return a.engine != b.engine ? a.engine > b.engine : a.secondsPerSecond < b.secondsPerSecond;
    });
    for (const BenchRun& r : rows) {
      front.rows.push_back({r.engine == "engine" ? "engine" : "Box2D", config(r),
                            sci(r.secondsPerSecond), sci(r.error)});
      front.rowClass.push_back(r.engine == "engine" ? "" : "mark");
    }
    doc.table(front);
  }

  if (!results.skip.empty()) {
    doc.heading("Skip study: what skipping unused stages buys");
    doc.paragraph(
        "World::plan() switches off every stage a scene cannot use. Each row times the same "
        "scene with stages switched on by changes that cannot alter its motion (unless said).");
    html::Table t{"ns per step (median)",
                  {"study", "balls", "variant", "ns / step", "same final state"},
                  {},
                  {}};
    for (const SkipRow& r : results.skip) {
      char ns[32];
      std::snprintf(ns, sizeof ns, "%.1f", r.nsPerStep);
      t.rows.push_back(
          {r.study, std::to_string(r.balls), r.variant, ns, r.sameResult ? "yes" : "no"});
    }
    doc.table(t);
    html::Plot p;
    p.title = "Broad phase: brute-force pairs against the uniform grid";
    p.xLabel = "balls";
    p.yLabel = "ns per step";
    p.logX = p.logY = true;
    html::Series brute{"brute force", {}, "linespoints", 7, 0},
        grid{"grid", {}, "linespoints", 5, 1};
    for (const SkipRow& r : results.skip) {
      if (r.study != "broad phase") continue;
      (r.variant == "grid" ? grid : brute).points.push_back({r.balls, r.nsPerStep});
    }
    p.series = {brute, grid};
    doc.plot(p);
  }
  doc.write(dir);
}

}  // namespace particles::cli
