#include <array>
#include <climits>
#include <string>

#include "json_values.h"
#include "particles/scene_output.h"
#include "readers.h"

namespace particles::scenefile {
namespace {

constexpr std::array<std::string_view, 2> kContactKeys{"restitution", "friction"};
constexpr std::array<std::string_view, 11> kSolverKeys{
    "contact_passes",     "correction_passes",          "grid_threshold",         "swept_walls",
    "swept_balls",        "sequential_impacts",         "velocity_shock",         "soft_substeps",
    "soft_contact_hertz", "soft_contact_damping_ratio", "soft_contact_push_speed"};

// Upper bound on both pass counts. A resting stack can use every pass of every
// step (docs/fuzzing.md, finding 1), so an unbounded count let a three-ball
// scene run for hours; 10,000 passes is far beyond what any scene here needs
// (the defaults are 64 and 8) and keeps a step of a small scene in milliseconds.
constexpr long long kMaxPasses = 10000;

// Upper bound on the soft step's substeps, for the same reason: every
// substep passes over every contact three times. The 100,000 pile rests
// with 16 (docs/scale.md, "The soft step"); 1,000 is far beyond that.
constexpr long long kMaxSubsteps = 1000;

// The soft step's keys (SolverSettings::scaleSubsteps and its spring). The
// spring's keys need substeps: without them the rigid step runs and would
// silently ignore them. The spring may be at most a quarter of the substep
// rate, the bound the engine clamps to: beyond it a pile jitters instead of
// coming to rest (docs/scale.md, "The soft step").
void readSoftStep(const Node& node, double dt, SolverSettings& solver) {
  if (auto n = node.optional("soft_substeps"))
    solver.scaleSubsteps = static_cast<int>(readInteger(*n, 0, kMaxSubsteps));
  for (const char* key :
       {"soft_contact_hertz", "soft_contact_damping_ratio", "soft_contact_push_speed"}) {
    auto v = node.optional(key);
    if (v && solver.scaleSubsteps == 0)
      v->fail(
          "needs \"soft_substeps\" >= 1 (without substeps the rigid step runs and has no "
          "contact spring)");
  }
  if (auto hz = node.optional("soft_contact_hertz")) {
    solver.scaleContactHertz = readPositive(*hz);
    const double most = softContactHertzMost(dt, solver.scaleSubsteps);
    if (solver.scaleContactHertz > most)
      hz->fail("must be at most a quarter of the substep rate, " + formatDouble(most) +
               " Hz with " + std::to_string(solver.scaleSubsteps) + " substeps of dt " +
               formatDouble(dt) + " s, got " + formatDouble(solver.scaleContactHertz));
  }
  if (auto z = node.optional("soft_contact_damping_ratio"))
    solver.scaleContactDampingRatio = readNonNegative(*z);
  if (auto v = node.optional("soft_contact_push_speed"))
    solver.scaleContactPushSpeed = readPositive(*v);
}

}  // namespace

ContactMaterial readContact(const Node& node) {
  node.allowKeys(kContactKeys);
  ContactMaterial material;  // restitution 1, friction 0
  if (auto e = node.optional("restitution")) material.restitution = readRestitution(*e);
  if (auto mu = node.optional("friction")) material.friction = readFriction(*mu);
  return material;
}

SolverSettings readSolver(const Node& node, double dt) {
  node.allowKeys(kSolverKeys);
  SolverSettings solver;
  if (auto n = node.optional("contact_passes"))
    solver.contactPasses = static_cast<int>(readInteger(*n, 1, kMaxPasses));
  if (auto n = node.optional("correction_passes"))
    solver.correctionPasses = static_cast<int>(readInteger(*n, 1, kMaxPasses));
  if (auto n = node.optional("grid_threshold"))
    solver.gridThreshold = static_cast<int>(readInteger(*n, 0, INT_MAX));
  if (auto b = node.optional("swept_walls")) solver.sweptWalls = readBool(*b);
  if (auto b = node.optional("swept_balls")) solver.sweptBalls = readBool(*b);
  if (auto b = node.optional("sequential_impacts")) solver.scaleSequentialImpacts = readBool(*b);
  if (auto b = node.optional("velocity_shock")) solver.scaleVelocityShock = readBool(*b);
  readSoftStep(node, dt, solver);
  return solver;
}

}  // namespace particles::scenefile
