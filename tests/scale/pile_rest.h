// Runs a pile for its rest, as the tests that count settled seeds need it
// (SettledPile.*): the criterion (pile_metrics.h), held over the
// last steps of the run.
#pragma once

#include <optional>
#include <vector>

#include "particles/pile/pile_metrics.h"
#include "particles/world.h"

namespace particles::pile {

struct RestRun {
  bool atRest = false;       // at rest over the last `atRestFor` steps at least
  double finalEnergy = 0.0;  // J, kinetic energy after the last step
};

// Steps `world` (built from `scene`) `steps` times, taking the kinetic
// energy after every step.
inline RestRun runForRest(World& world, const SceneDef& scene, long long steps,
                          long long atRestFor) {
  std::vector<double> energy;
  energy.reserve(static_cast<std::size_t>(steps));
  for (long long s = 0; s < steps; ++s) {
    world.step();
    energy.push_back(kineticEnergy(world.balls(), scene.balls));
  }
  const std::optional<long long> rest = restStep(energy, restEnergy(scene.balls));
  return {rest && *rest <= steps - atRestFor, energy.empty() ? 0.0 : energy.back()};
}

}  // namespace particles::pile
