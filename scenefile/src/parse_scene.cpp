// The top level of a scene file; the parts are read in readers.h.
#include <array>

#include "initial_overlaps.h"
#include "json_values.h"
#include "parse_json.h"
#include "particles/scenefile.h"
#include "readers.h"

namespace particles {
namespace {

using scenefile::Node;

constexpr std::array<std::string_view, 10> kTopKeys{
    "name", "gravity", "contact", "walls", "box", "balls", "forces", "dt", "duration", "solver"};
constexpr std::array<std::string_view, 4> kBoxWallNames{"box bottom wall", "box right wall",
                                                        "box top wall", "box left wall"};

std::string where(const Node& node) {
  return node.file() + ": " + node.path();
}

}  // namespace

SceneDef parseScene(std::string_view text, const std::string& fileName) {
  const nlohmann::json doc = scenefile::parseJson(text, fileName);
  const Node root(doc, "", fileName);
  if (!doc.is_object()) root.fail("must be a JSON object {...}, got " + scenefile::describe(doc));
  root.allowKeys(kTopKeys);

  SceneDef scene;
  if (auto n = root.optional("name")) scene.name = scenefile::readString(*n);
  if (auto g = root.optional("gravity")) scene.gravity = scenefile::readVec2(*g);
  if (auto c = root.optional("contact")) scene.contact = scenefile::readContact(*c);

  std::vector<std::string> wallNames;
  if (auto walls = root.optional("walls")) {
    for (const Node& w : walls->elements()) {
      scene.walls.push_back(scenefile::readWall(w));
      wallNames.push_back(w.path());
    }
  }
  if (auto box = root.optional("box")) {
    for (const WallDef& w : scenefile::readBox(*box)) scene.walls.push_back(w);
    wallNames.insert(wallNames.end(), kBoxWallNames.begin(), kBoxWallNames.end());
  }

  const Node balls = root.required("balls");
  for (const Node& b : balls.elements()) scene.balls.push_back(scenefile::readBall(b));
  if (scene.balls.empty()) balls.fail("must list at least one ball");

  if (auto forces = root.optional("forces"))
    for (const Node& f : forces->elements())
      scene.forces.push_back(scenefile::readForce(f, scene.balls.size()));

  if (auto dt = root.optional("dt")) {
    scene.dt = scenefile::readNumber(*dt);
    checkTimeStep(scene.dt, where(*dt));
  }
  if (auto duration = root.optional("duration")) {
    scene.duration = scenefile::readNumber(*duration);
    checkDuration(scene.duration, where(*duration));
  }
  checkStepCount(scene.duration, scene.dt, fileName + ": duration");
  if (auto s = root.optional("solver")) scene.solver = scenefile::readSolver(*s, scene.dt);

  scenefile::checkInitialOverlaps(scene, wallNames, fileName);
  return scene;
}

}  // namespace particles
