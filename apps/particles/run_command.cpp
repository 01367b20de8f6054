// particles run SCENE.json: load, simulate, print the final state.
#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "commands.h"
#include "particles/scenefile.h"
#include "particles/world.h"

namespace particles::cli {
namespace {

constexpr const char* kSummary =
    "Load SCENE.json, run round(duration / dt) fixed steps, print the final state as JSON";

constexpr const char* kFooter = R"(Output (stdout): the final state, one line of JSON,
  {"time": T, "balls": [{"position": [x, y], "velocity": [vx, vy],
                         "angle": a, "angular_velocity": w}, ...]}
with the balls in the file's order. Units: s, m, m/s, rad, rad/s.
CSV (--csv): header t,id,x,y,angle,vx,vy,omega; one row per ball (id = index in
the file) at t = 0 and after every N-th step; shortest round-trip numbers.
Exit status:
  0  success (a warning on stderr if the contact-pass bound was reached)
  1  the simulation diverged (non-finite state): nothing on stdout
  2  a bad scene file or bad arguments: one line on stderr,
     "particles: error: FILE: JSON_PATH: problem"
Scene format (keys, units, defaults, checks): docs/scene-format.md.
)";

// How often the run checks, between CSV rows, that the state is still finite.
constexpr long long kFiniteCheckInterval = 1000;

struct RunOptions {
  std::string scene;
  std::optional<double> dt, duration;
  std::string csv;
  long long csvEvery = 1;
};

void error(const std::string& message) {
  std::cerr << "particles: error: " << message << '\n';
}

// The scene with the command line's overrides, validated like the file.
SceneDef prepareScene(const RunOptions& o) {
  if (o.dt) checkTimeStep(*o.dt, "--dt");
  if (o.duration) checkDuration(*o.duration, "--duration");
  if (o.csvEvery < 1)
    throw SceneError("--csv-every: must be an integer >= 1, got " + std::to_string(o.csvEvery));
  SceneDef scene = loadScene(o.scene);
  if (o.dt) scene.dt = *o.dt;
  if (o.duration) scene.duration = *o.duration;
  if (o.dt || o.duration) checkStepCount(scene.duration, scene.dt, "--dt/--duration");
  return scene;
}

// Steps the world, writing CSV rows at t = 0 and after every `every`-th step.
// Returns the step after which a non-finite state was seen, 0 if none was:
// checked at each CSV row, every kFiniteCheckInterval steps and at the end.
long long simulate(World& world, long long steps, CsvTrajectoryWriter* csv, long long every) {
  if (csv) csv->write(world);
  for (long long k = 1; k <= steps; ++k) {
    world.step();
    const bool row = csv != nullptr && k % every == 0;
    if ((row || k % kFiniteCheckInterval == 0 || k == steps) && !allFinite(world)) return k;
    if (row) csv->write(world);
  }
  return 0;
}

// The run is deterministic, so replaying it step by step finds the first
// non-finite step exactly, at no cost to runs that stay finite.
long long firstNonFiniteStep(const SceneDef& scene, long long detectedAt) {
  World replay(scene);
  for (long long k = 1; k < detectedAt; ++k) {
    replay.step();
    if (!allFinite(replay)) return k;
  }
  return detectedAt;
}

int run(const RunOptions& o) {
  SceneDef scene;
  try {
    scene = prepareScene(o);
  } catch (const SceneError& e) {
    error(e.what());
    return kExitBadInput;
  }

  std::ofstream csvFile;
  std::optional<CsvTrajectoryWriter> csv;
  if (!o.csv.empty()) {
    csvFile.open(o.csv, std::ios::binary | std::ios::trunc);
    if (!csvFile) {
      error("--csv: cannot open '" + o.csv + "' for writing");
      return kExitBadInput;
    }
    csv.emplace(csvFile);
  }

  World world(scene);
  const long long diverged = simulate(world, scene.stepCount(), csv ? &*csv : nullptr, o.csvEvery);
  if (diverged > 0) {
    const long long k = firstNonFiniteStep(scene, diverged);
    error(o.scene + ": the simulation diverged (non-finite state) at step " + std::to_string(k) +
          " (t = " + formatDouble(static_cast<double>(k) * scene.dt) + " s)");
    return kExitFailed;
  }
  if (csv) {
    csvFile.close();
    if (!csvFile) {
      error("--csv: error writing '" + o.csv + "'");
      return kExitFailed;
    }
  }

  std::cout << finalStateText(world) << '\n' << std::flush;
  const StepStats& stats = world.stats();
  if (stats.passLimitHits > 0)
    std::cerr << "particles: warning: the contact-pass bound (" << scene.solver.contactPasses
              << ") was reached in " << stats.passLimitHits
              << " steps; velocities may still approach there\n";
  return std::cout ? kExitOk : kExitFailed;
}

}  // namespace

void addRunCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand("run", kSummary);
  cmd->footer(kFooter);
  auto o = std::make_shared<RunOptions>();
  cmd->add_option("scene", o->scene, "Scene file, JSON (docs/scene-format.md)")
      ->required()
      ->type_name("SCENE.json");
  auto* dt =
      cmd->add_option("--dt", "Time step, s, > 0 (overrides the file's \"dt\"; default 0.001)")
          ->type_name("S");
  auto* duration =
      cmd->add_option("--duration",
                      "Simulated time, s, >= 0 (overrides the file's \"duration\"; default 1)")
          ->type_name("S");
  cmd->add_option("--csv", o->csv, "Also write the trajectory to FILE as CSV (see below)")
      ->type_name("FILE");
  cmd->add_option("--csv-every", o->csvEvery, "CSV rows after every N-th step, integer >= 1")
      ->type_name("N")
      ->default_val(1);
  cmd->callback([o, dt, duration, &action] {
    if (dt->count() > 0) o->dt = dt->as<double>();
    if (duration->count() > 0) o->duration = duration->as<double>();
    action = [o] {
      try {
        return run(*o);
      } catch (const std::exception& e) {  // not expected: the scene was validated
        error(std::string("internal error: ") + e.what());
        return kExitFailed;
      }
    };
  });
}

}  // namespace particles::cli
