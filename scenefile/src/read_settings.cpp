#include <array>
#include <climits>

#include "json_values.h"
#include "readers.h"

namespace particles::scenefile {
namespace {

constexpr std::array<std::string_view, 2> kContactKeys{"restitution", "friction"};
constexpr std::array<std::string_view, 3> kSolverKeys{"contact_passes", "correction_passes",
                                                      "grid_threshold"};

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
    solver.contactPasses = static_cast<int>(readInteger(*n, 1, INT_MAX));
  if (auto n = node.optional("correction_passes"))
    solver.correctionPasses = static_cast<int>(readInteger(*n, 1, INT_MAX));
  if (auto n = node.optional("grid_threshold"))
    solver.gridThreshold = static_cast<int>(readInteger(*n, 0, INT_MAX));
  return solver;
}

}  // namespace particles::scenefile
