#include <array>
#include <climits>

#include "json_values.h"
#include "readers.h"

namespace particles::scenefile {
namespace {

constexpr std::array<std::string_view, 2> kContactKeys{"restitution", "friction"};
constexpr std::array<std::string_view, 5> kSolverKeys{
    "contact_passes", "correction_passes", "grid_threshold", "swept_walls", "swept_balls"};

// Upper bound on both pass counts. A resting stack can use every pass of every
// step (docs/fuzzing.md, finding 1), so an unbounded count let a three-ball
// scene run for hours; 10,000 passes is far beyond what any scene here needs
// (the defaults are 64 and 8) and keeps a step of a small scene in milliseconds.
constexpr long long kMaxPasses = 10000;

}  // namespace

ContactMaterial readContact(const Node& node) {
  node.allowKeys(kContactKeys);
  ContactMaterial material;  // restitution 1, friction 0
  if (auto e = node.optional("restitution")) material.restitution = readRestitution(*e);
  if (auto mu = node.optional("friction")) material.friction = readFriction(*mu);
  return material;
}

SolverSettings readSolver(const Node& node) {
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
  return solver;
}

}  // namespace particles::scenefile
