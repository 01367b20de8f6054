// particles stress: the stability envelope (docs/stress.md). Every case runs
// in the engine and in its Box2D twin, is classified stable or broken, and
// every broken case is written as a scene file that `particles run` and
// `particles compare` replay.
#include <CLI/CLI.hpp>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "csv_field.h"
#include "particles/html/document.h"
#include "particles/reference/box2d_settings.h"
#include "particles/scene_output.h"
#include "particles/scene_writer.h"
#include "particles/timestep/stress.h"
#include "suite_output.h"

namespace particles::cli {
namespace {

namespace fs = std::filesystem;
using timestep::StressCase;
using timestep::StressObservation;
using timestep::Verdict;

struct StressOptions {
  std::string out = "stress";
  bool outGiven = false;  // --out on the command line; without it --report DIR takes everything
  std::string report;
  bool longGas = false;
  bool sweptWalls = false;  // the engine with SolverSettings::sweptWalls
  bool sweptBalls = false;  // the engine with SolverSettings::sweptBalls
};

struct StressRow {
  const StressCase* c;
  StressObservation engine, box2d;
  Verdict engineVerdict, box2dVerdict;
  std::string scenePath;  // written when either engine broke
};

std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2e", x);
  return buf;
}

std::string fileName(const StressCase& c) {
  std::string s = c.axis + "_" + c.value;
  for (char& ch : s)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '.' && ch != '-') ch = '_';
  return s + ".json";
}

// A relative path as a URL path: bytes outside the unreserved set (and '/')
// percent-encoded, so a directory name with a space or '#' still links.
std::string urlPath(const fs::path& p) {
  static const char* hex = "0123456789ABCDEF";
  std::string u;
  for (const char ch : p.generic_string()) {
    const auto c = static_cast<unsigned char>(ch);
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
      u += ch;
    } else {
      u += '%';
      u += hex[c >> 4];
      u += hex[c & 15];
    }
  }
  return u;
}

std::string verdictText(const Verdict& v) {
  return v.stable ? "stable" : "BROKEN (" + v.reasons + ")";
}

void writeCsv(const fs::path& file, const std::vector<StressRow>& rows) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  out << "axis,value,engine_stable,engine_reasons,box2d_stable,box2d_reasons,"
         "engine_energy_growth,box2d_energy_growth,engine_overlap_at_rest,box2d_overlap_at_rest,"
         "engine_kinetic_at_end_J,box2d_kinetic_at_end_J,scene_file\n";
  auto growth = [](const StressObservation& o) {
    return o.finite ? formatDouble((o.energyMax - o.energyStart) / o.energyScale) : "";
  };
  for (const StressRow& r : rows)
    out << csvField(r.c->axis) << ',' << csvField(r.c->value) << ',' << r.engineVerdict.stable
        << ',' << csvField(r.engineVerdict.reasons) << ',' << r.box2dVerdict.stable << ','
        << csvField(r.box2dVerdict.reasons) << ',' << growth(r.engine) << ',' << growth(r.box2d)
        << ',' << (r.engine.atRest ? formatDouble(r.engine.overlapAtRest) : "") << ','
        << (r.box2d.atRest ? formatDouble(r.box2d.overlapAtRest) : "") << ','
        << formatDouble(r.engine.kineticAtEnd) << ',' << formatDouble(r.box2d.kineticAtEnd) << ','
        << csvField(r.scenePath) << '\n';
  if (!out) throw std::runtime_error("error writing " + file.string());
}

void writeReport(const fs::path& dir, const std::vector<StressRow>& rows, bool longGas,
                 bool sweptWalls, bool sweptBalls) {
  html::Document doc("particles stress: the stability envelope");
  doc.paragraph(
      "Each case runs in the engine and in its Box2D 2.4.1 twin (continuous physics off, as the "
      "engine). Stable means: no NaN or infinity, total energy (kinetic + rotational + "
      "potential) never more than 1 % of the case's energy scale above its start, no ball through "
      "a wall or another ball, and for a case that ends at rest an overlap below 1 % of the "
      "radius. Broken cases are written as scene files (column \"scene\") that particles run and "
      "particles compare replay. Elastic gas: " +
      std::string(longGas ? "1e6" : "1e4") + " steps." +
      (sweptWalls ? " The engine ran with continuous collision against walls (--swept-walls)."
                  : "") +
      (sweptBalls ? " The engine ran with continuous collision between balls (--swept-balls)."
                  : ""));
  html::Table t{
      "Envelope",
      {"axis", "value", "engine", "Box2D", "overlap at rest (engine / Box2D, / r)", "scene"},
      {},
      {}};
  for (const StressRow& r : rows) {
    t.rows.push_back(
        {r.c->axis, r.c->value, verdictText(r.engineVerdict), verdictText(r.box2dVerdict),
         r.engine.atRest ? sci(r.engine.overlapAtRest) + " / " + sci(r.box2d.overlapAtRest) : "",
         r.scenePath});
    t.rowClass.push_back(r.engineVerdict.stable && r.box2dVerdict.stable ? "good" : "bad");
    // The link is relative to index.html (the scene file exists by now), so
    // the report opens from anywhere and survives being moved with its scenes.
    t.links.push_back({});
    if (!r.scenePath.empty())
      t.links.back() = {"", "", "", "", "", urlPath(fs::relative(r.scenePath, dir))};
  }
  doc.table(t);
  // One plot per engine: energy growth along the case list, log scale.
  html::Plot p;
  p.title = "Largest energy growth per case (fraction of the energy scale; 1e-16 = none)";
  p.xLabel = "case number (table order)";
  p.yLabel = "energy growth";
  p.logY = true;
  html::Series e{"engine", {}, "points", 7, 0}, b{"Box2D", {}, "points", 5, 1},
      limit{"1 % limit", {}, "lines", 0, 3};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    auto g = [](const StressObservation& o) {
      return o.finite ? std::max((o.energyMax - o.energyStart) / o.energyScale, 1e-16) : 1e3;
    };
    e.points.push_back({static_cast<double>(i + 1), g(rows[i].engine)});
    b.points.push_back({static_cast<double>(i + 1), g(rows[i].box2d)});
  }
  limit.points = {{1.0, 0.01}, {static_cast<double>(rows.size()), 0.01}};
  p.series = {e, b, limit};
  doc.plot(p);
  doc.note("Non-finite runs are drawn at 1e3.");
  doc.write(dir);
}

int stress(const StressOptions& o) {
  // One directory for everything when only --report is given: the report's
  // links then point at scenes beside it.
  const fs::path out = o.report.empty() || o.outGiven ? fs::path(o.out) : fs::path(o.report);
  const bool separateReport =
      !o.report.empty() && fs::weakly_canonical(out) != fs::weakly_canonical(o.report);
  if (!prepareReportDir(out)) return kExitBadInput;
  if (separateReport && !prepareReportDir(o.report)) return kExitBadInput;
  const std::vector<StressCase> cases = timestep::stressCases(o.longGas);
  std::vector<StressRow> rows;
  for (const StressCase& c : cases) {
    std::cerr << "stress: " << c.axis << " " << c.value << "..." << std::endl;
    const long long every = c.scene.balls.size() > 50 ? 100 : 1;
    StressRow r{&c, {}, {}, {}, {}, {}};
    // The scene the engine ran, switches included: it is also what a broken
    // case's file records, so `particles run` replays this run.
    SceneDef scene = c.scene;
    scene.solver.sweptWalls = o.sweptWalls;
    scene.solver.sweptBalls = o.sweptBalls;
    {
      auto s = timestep::engineStepper(scene);
      r.engine = timestep::observeStress(*s, c, every);
    }
    {
      auto s = timestep::box2dStepper(c.scene, reference::Box2DSettings::forScene(c.scene));
      r.box2d = timestep::observeStress(*s, c, every);
    }
    r.engineVerdict = timestep::classify(r.engine);
    r.box2dVerdict = timestep::classify(r.box2d);
    if (!r.engineVerdict.stable || !r.box2dVerdict.stable) {
      fs::create_directories(out / "broken");
      const fs::path file = out / "broken" / fileName(c);
      std::ofstream f(file);
      f << sceneText(scene);
      if (!f) throw std::runtime_error("cannot write " + file.string());
      r.scenePath = file.string();
    }
    rows.push_back(r);
  }
  writeCsv(out / "envelope.csv", rows);
  if (separateReport) writeCsv(fs::path(o.report) / "envelope.csv", rows);
  if (!o.report.empty()) writeReport(o.report, rows, o.longGas, o.sweptWalls, o.sweptBalls);
  std::printf("%-14s %-12s %-44s %s\n", "axis", "value", "engine", "Box2D");
  int broken = 0;
  for (const StressRow& r : rows) {
    std::printf("%-14s %-12s %-44s %s\n", r.c->axis.c_str(), r.c->value.c_str(),
                verdictText(r.engineVerdict).c_str(), verdictText(r.box2dVerdict).c_str());
    if (r.c->endsAtRest)
      std::printf("%-27s overlap at rest %s r, kinetic energy %s J | overlap %s r, kinetic %s J\n",
                  "", sci(r.engine.overlapAtRest).c_str(), sci(r.engine.kineticAtEnd).c_str(),
                  sci(r.box2d.overlapAtRest).c_str(), sci(r.box2d.kineticAtEnd).c_str());
    broken += !r.scenePath.empty();
  }
  std::printf("%d cases, %d with a broken engine or Box2D (scenes in %s); CSV: %s%s\n",
              static_cast<int>(rows.size()), broken, (out / "broken").string().c_str(),
              (out / "envelope.csv").string().c_str(),
              o.report.empty() ? "" : ("; report: " + o.report + "/index.html").c_str());
  return std::fflush(stdout) == 0 ? kExitOk : kExitFailed;
}

}  // namespace

void addStressCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand(
      "stress",
      "Map the numerical stability envelope of the engine and Box2D; write broken cases as scenes");
  cmd->footer(R"(Axes: mass ratio 1e-6..1e6, radius ratio 1e-3..1e3, speed 0.1..5 radii per step
(into a wall and into a ball), grazing impacts, a long elastic gas, dense piles
(overlap and kinetic energy at rest), scene scale 1e-4..1e4. Stable: no NaN or
infinity, energy growth <= 1 % of the case's energy scale, no tunnelling,
overlap at rest < 1 % of the radius (docs/stress.md).
Writes OUT/envelope.csv and OUT/broken/*.json (replay with 'particles run' or
'particles compare'); with --report DIR and no --out, all of it goes to DIR
beside index.html, whose scene links are relative to it. Exit status: 0 when the map was made (broken cases are
findings, not failures); 1 on an I/O error; 2 on bad arguments.)");
  auto o = std::make_shared<StressOptions>();
  CLI::Option* out =
      cmd->add_option("--out", o->out,
                      "Directory for envelope.csv and broken/*.json, created if missing "
                      "(default: the --report DIR if given, else stress)")
          ->type_name("DIR");
  cmd->add_option("--report", o->report,
                  "Also write DIR/index.html (envelope table and plot); without --out, the CSV "
                  "and the broken scenes go to DIR too")
      ->type_name("DIR");
  cmd->add_flag("--long", o->longGas, "Run the elastic gas for 1e6 steps instead of 1e4");
  cmd->add_flag(
      "--swept-walls", o->sweptWalls,
      "Run the engine with continuous collision against walls (SolverSettings::sweptWalls; "
      "the written scenes carry it as solver.swept_walls)");
  cmd->add_flag("--swept-balls", o->sweptBalls,
                "Run the engine with continuous collision between balls "
                "(SolverSettings::sweptBalls; the written scenes carry it as solver.swept_balls)");
  cmd->callback([o, out, &action] {
    o->outGiven = out->count() > 0;
    action = [o] {
      try {
        return stress(*o);
      } catch (const std::exception& e) {
        printError(std::string("internal error: ") + e.what());
        return kExitFailed;
      }
    };
  });
}

}  // namespace particles::cli
