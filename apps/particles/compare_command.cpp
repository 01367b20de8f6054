// particles compare SCENE.json...: each scene in the engine and in its Box2D
// twin side by side, collision by collision (compare::compareScene).
#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "cli_common.h"
#include "commands.h"
#include "particles/compare/scene_compare.h"
#include "particles/scenefile.h"

namespace particles::cli {
namespace {

constexpr const char* kSummary =
    "Run each scene in the engine and in its Box2D twin, match their collision events and "
    "report the differences";

constexpr const char* kFooter =
    R"(What it does: each SCENE.json runs for round(duration / dt) steps in both
engines side by side. A collision event is a contact that exchanged a normal
impulse during a step: a ball pair, or a ball and a wall. Events of the same
pair whose steps differ by at most --window steps are matched; the rest are
"engine only" or "Box2D only". For matched events the velocities after the
step are compared.
Output (stdout), per scene:
  FILE: STEPS steps, M matched collision events, E engine only, B Box2D only
    outside Box2D's range: ...                      (each range issue)
    largest post-collision difference: balls[i]-walls[j] at t = T s:
      |dv| = m/s, |dw| = rad/s (relative: over the speed scale before)
    engine only: ... / Box2D only: ...             (the first 5 of each)
--json FILE writes a JSON array with one object per scene, in argument order:
  {"scene", "steps", "outside_box2d_range": [messages],
   "worst_relative_difference",
   "matched": [{"engine": EVENT, "box2d": EVENT,
                "difference": {"velocity" m/s, "spin" rad/s, "relative"}}],
   "engine_only": [EVENT], "box2d_only": [EVENT],
   "final": [{"ball", "position_difference" m, "velocity_difference" m/s,
              "angular_velocity_difference" rad/s}]}
  EVENT = {"a", "b", "wall", "step", "time" s, "bodies": [{"ball",
           "before": {"velocity": [vx, vy], "angular_velocity"}, "after": ...}]}
(docs/cli.md has the details). compare reports; it does not judge: a
difference is not an error.
Exit status:
  0  every scene was compared (whatever the differences)
  1  an I/O error (writing --json) or an internal error
  2  a bad scene file or bad arguments: one line on stderr,
     "particles: error: FILE: JSON_PATH: problem"; nothing is compared
)";

struct CompareOptions {
  std::vector<std::string> scenes;
  std::string json;
  Box2DIterations iterations;
  int window = 2;
};

int compare(const CompareOptions& o) {
  // Every scene is checked before any is run: a bad file costs nothing.
  std::vector<SceneDef> scenes;
  try {
    for (const std::string& file : o.scenes) scenes.push_back(loadScene(file));
  } catch (const SceneError& e) {
    printError(e.what());
    return kExitBadInput;
  }
  std::ofstream jsonFile;
  if (!o.json.empty()) {
    jsonFile.open(o.json, std::ios::binary | std::ios::trunc);
    if (!jsonFile) {
      printError("--json: cannot open '" + o.json + "' for writing");
      return kExitBadInput;
    }
  }

  compare::CompareSettings settings;
  settings.box2d.velocityIterations = o.iterations.velocity;
  settings.box2d.positionIterations = o.iterations.position;
  settings.matchWindowSteps = o.window;

  nlohmann::json all = nlohmann::json::array();
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    settings.box2d.dt = scenes[i].dt;  // compareScene takes dt from the scene anyway
    const compare::SceneComparison c = compare::compareScene(scenes[i], o.scenes[i], settings);
    std::cout << compare::comparisonText(c) << std::flush;
    if (jsonFile.is_open()) all.push_back(compare::comparisonJson(c));
  }
  if (jsonFile.is_open()) {
    jsonFile << all.dump(1) << '\n';
    jsonFile.close();
    if (!jsonFile) {
      printError("--json: error writing '" + o.json + "'");
      return kExitFailed;
    }
  }
  return std::cout ? kExitOk : kExitFailed;
}

}  // namespace

void addCompareCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand("compare", kSummary);
  cmd->footer(kFooter);
  auto o = std::make_shared<CompareOptions>();
  cmd->add_option("scenes", o->scenes, "Scene files, JSON (docs/scene-format.md); one or more")
      ->required()
      ->type_name("SCENE.json");
  cmd->add_option("--json", o->json,
                  "Also write the comparisons to FILE: a JSON array, one object per scene")
      ->type_name("FILE");
  addBox2DIterationOptions(*cmd, o->iterations);
  cmd->add_option("--window", o->window,
                  "Events of the same pair at most STEPS steps apart are the same collision, "
                  "integer 0 to 1000000")
      ->type_name("STEPS")
      ->default_val(o->window)
      ->check(integerInRange(0, 1000000));
  cmd->callback([o, &action] {
    action = [o] {
      try {
        return compare(*o);
      } catch (const std::exception& e) {  // not expected: the scenes were validated
        printError(std::string("internal error: ") + e.what());
        return kExitFailed;
      }
    };
  });
}

}  // namespace particles::cli
