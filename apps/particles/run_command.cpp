// particles run SCENE.json: load, simulate in the engine or in its Box2D
// twin, print the final state.
#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "cli_common.h"
#include "commands.h"
#include "particles/reference/box2d_range.h"
#include "particles/reference/box2d_world.h"
#include "particles/scenefile.h"
#include "particles/state_hash.h"
#include "particles/world.h"

namespace particles::cli {
namespace {

constexpr const char* kSummary =
    "Load SCENE.json, run round(duration / dt) fixed steps in the engine or in Box2D, print the "
    "final state as JSON";

constexpr const char* kFooter = R"(Engines (--engine):
  engine  the hand-written impulse solver (double precision), the default
  box2d   the scene's Box2D 2.4.1 twin (float precision; docs/box2d-twin.md),
          stepped with --velocity-iterations and --position-iterations.
          Each way the scene leaves Box2D's range is a warning on stderr,
          "particles: warning: outside Box2D's range: ...", not an error.
Output (stdout): the final state, one line of JSON, the same for both engines,
  {"time": T, "balls": [{"position": [x, y], "velocity": [vx, vy],
                         "angle": a, "angular_velocity": w}, ...]}
with the balls in the file's order. Units: s, m, m/s, rad, rad/s.
CSV (--csv): header t,id,x,y,angle,vx,vy,omega; one row per ball (id = index in
the file) at t = 0 and after every N-th step; shortest round-trip numbers.
Exit status:
  0  success (warnings on stderr: the engine's contact-pass bound was reached,
     the scene is outside Box2D's range, Box2D clamped a speed or spin)
  1  the simulation diverged (non-finite state): nothing on stdout
  2  a bad scene file or bad arguments: one line on stderr,
     "particles: error: FILE: JSON_PATH: problem"
     (also more than --max-steps steps: nothing is run)
Scene format (keys, units, defaults, checks): docs/scene-format.md.
)";

// Default of --max-steps: about 10 s for one ball, minutes for a few dozen;
// more is almost always a unit slip in dt or duration (docs/cli.md).
constexpr long long kDefaultMaxSteps = 100000000;

// How often the run checks, between CSV rows, that the state is still finite.
constexpr long long kFiniteCheckInterval = 1000;

struct RunOptions {
  std::string scene;
  std::optional<double> dt, duration;
  std::string csv;
  long long csvEvery = 1;
  std::string engine = "engine";
  Box2DIterations iterations;
  long long maxSteps = kDefaultMaxSteps;  // 0: no limit
  bool hash = false;
};

// ---- Reading a state from either world -----------------------------------
// Box2DWorld reads like World (ballCount, ball, balls, time); scenefile's
// output helpers take a World, or a time and the balls, so a Box2D state is
// printed from its balls(). Both paths print through the same code.

bool finiteState(const World& world) {
  return allFinite(world);
}
bool finiteState(const reference::Box2DWorld& world) {
  return allFinite(world.balls());
}

void writeRows(CsvTrajectoryWriter& csv, const World& world) {
  csv.write(world);
}
void writeRows(CsvTrajectoryWriter& csv, const reference::Box2DWorld& world) {
  csv.write(world.time(), world.balls());
}

std::uint64_t stateHashOf(const World& world) {
  return stateHash(world);
}
std::uint64_t stateHashOf(const reference::Box2DWorld& world) {
  return stateHash(world.balls());
}

std::string stateText(const World& world) {
  return finalStateText(world);
}
std::string stateText(const reference::Box2DWorld& world) {
  return finalStateText(world.time(), world.balls());
}

// ---- The run ----------------------------------------------------------------

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
  // A guard, not a check of the scene: 1e12 steps are legal but would run
  // for days without a word.
  if (o.maxSteps > 0 && scene.stepCount() > o.maxSteps)
    throw SceneError(o.scene + ": duration / dt = " + std::to_string(scene.stepCount()) +
                     " steps, more than --max-steps " + std::to_string(o.maxSteps) +
                     "; raise --max-steps, or 0 for no limit");
  return scene;
}

// Steps the world, writing CSV rows at t = 0 and after every `every`-th step.
// Returns the step after which a non-finite state was seen, 0 if none was:
// checked at each CSV row, every kFiniteCheckInterval steps and at the end.
template <typename W>
long long simulate(W& world, long long steps, CsvTrajectoryWriter* csv, long long every) {
  if (csv) writeRows(*csv, world);
  for (long long k = 1; k <= steps; ++k) {
    world.step();
    const bool row = csv != nullptr && k % every == 0;
    if ((row || k % kFiniteCheckInterval == 0 || k == steps) && !finiteState(world)) return k;
    if (row) writeRows(*csv, world);
  }
  return 0;
}

// Both engines are deterministic, so replaying the run step by step finds
// the first non-finite step exactly, at no cost to runs that stay finite.
template <typename W>
long long firstNonFiniteStep(W replay, long long detectedAt) {
  for (long long k = 1; k < detectedAt; ++k) {
    replay.step();
    if (!finiteState(replay)) return k;
  }
  return detectedAt;
}

void warnPassLimit(const World& world) {
  const StepStats& stats = world.stats();
  if (stats.passLimitHits > 0)
    printWarning("the contact-pass bound (" + std::to_string(world.scene().solver.contactPasses) +
                 ") was reached in " + std::to_string(stats.passLimitHits) +
                 " steps; velocities may still approach there");
}

void warnClamps(const reference::Box2DWorld& world) {
  const reference::Box2DLimitHits& hits = world.limitHits();
  if (hits.translation > 0)
    printWarning("Box2D clamped a ball's speed to 2 m per step (b2_maxTranslation) in " +
                 std::to_string(hits.translation) + " steps");
  if (hits.rotation > 0)
    printWarning("Box2D clamped a ball's spin to pi/2 per step (b2_maxRotation) in " +
                 std::to_string(hits.rotation) + " steps");
}

// Runs `world` to the end, then prints its final state; make() builds a
// fresh copy of it for the replay after a divergence.
template <typename W, typename Make>
int execute(const RunOptions& o, const SceneDef& scene, W& world, const Make& make) {
  std::ofstream csvFile;
  std::optional<CsvTrajectoryWriter> csv;
  if (!o.csv.empty()) {
    csvFile.open(o.csv, std::ios::binary | std::ios::trunc);
    if (!csvFile) {
      printError("--csv: cannot open '" + o.csv + "' for writing");
      return kExitBadInput;
    }
    csv.emplace(csvFile);
  }

  const long long diverged = simulate(world, scene.stepCount(), csv ? &*csv : nullptr, o.csvEvery);
  if (diverged > 0) {
    const long long k = firstNonFiniteStep(make(), diverged);
    printError(o.scene + ": the simulation diverged (non-finite state) at step " +
               std::to_string(k) + " (t = " + formatDouble(static_cast<double>(k) * scene.dt) +
               " s)");
    return kExitFailed;
  }
  if (csv) {
    csvFile.close();
    if (!csvFile) {
      printError("--csv: error writing '" + o.csv + "'");
      return kExitFailed;
    }
  }

  std::cout << stateText(world) << '\n' << std::flush;
  if (o.hash) std::cerr << "state-hash: " << hashHex(stateHashOf(world)) << '\n';
  if constexpr (std::is_same_v<W, World>)
    warnPassLimit(world);
  else
    warnClamps(world);
  return std::cout ? kExitOk : kExitFailed;
}

int run(const RunOptions& o) {
  SceneDef scene;
  try {
    scene = prepareScene(o);
  } catch (const SceneError& e) {
    printError(e.what());
    return kExitBadInput;
  }

  if (o.engine == "box2d") {
    reference::Box2DSettings settings = reference::Box2DSettings::forScene(scene);
    settings.velocityIterations = o.iterations.velocity;
    settings.positionIterations = o.iterations.position;
    printRangeWarnings(reference::checkBox2DRange(scene, settings));
    std::optional<reference::Box2DWorld> world;
    try {
      world.emplace(scene, settings);
    } catch (const std::invalid_argument& e) {  // not expected after the loader's checks
      printError(o.scene + ": Box2D cannot represent this scene: " + e.what());
      return kExitBadInput;
    }
    return execute(o, scene, *world, [&] { return reference::Box2DWorld(scene, settings); });
  }
  World world(scene);
  return execute(o, scene, world, [&] { return World(scene); });
}

}  // namespace

void addRunCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand("run", kSummary);
  cmd->footer(kFooter);
  auto o = std::make_shared<RunOptions>();
  cmd->add_option("scene", o->scene, "Scene file, JSON (docs/scene-format.md)")
      ->required()
      ->type_name("SCENE.json");
  cmd->add_option("--engine", o->engine,
                  "Which solver runs the scene: engine (the impulse solver) or box2d (its "
                  "Box2D 2.4.1 twin); default engine")
      ->type_name("NAME")
      ->check(CLI::IsMember({"engine", "box2d"}));
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
  cmd->add_option("--max-steps", o->maxSteps,
                  "Refuse (exit 2) a run of more than N steps, integer >= 0; 0 = no limit")
      ->type_name("N")
      ->default_val(o->maxSteps)
      ->check(integerInRange(0, std::numeric_limits<long long>::max()));
  cmd->add_flag("--hash", o->hash,
                "Also print 'state-hash: <16 hex digits>' on stderr: FNV-1a 64 of the final "
                "state (docs/determinism.md)");
  const Box2DIterationOptions iterations =
      addBox2DIterationOptions(*cmd, o->iterations, " (with --engine box2d only)");
  cmd->callback([o, dt, duration, iterations, &action] {
    if (o->engine != "box2d") {
      for (const CLI::Option* opt : {iterations.velocity, iterations.position})
        if (opt->count() > 0)
          throw CLI::ValidationError(opt->get_name(), "applies only to --engine box2d");
    }
    if (dt->count() > 0) o->dt = dt->as<double>();
    if (duration->count() > 0) o->duration = duration->as<double>();
    action = [o] {
      try {
        return run(*o);
      } catch (const StepError& e) {  // a state the run reached, not the file
        printError(o->scene + ": " + e.what());
        return kExitFailed;
      } catch (const std::exception& e) {  // not expected: the scene was validated
        printError(std::string("internal error: ") + e.what());
        return kExitFailed;
      }
    };
  });
}

}  // namespace particles::cli
