// The one failure of a step on a valid scene: a state that cannot be
// stepped within bounded memory. The scene loader rejects bad input before
// any step (docs/scene-format.md); this is for states the simulation itself
// reaches, as when a solver setting that holds a deep pile up is switched
// off and the pile blows up (docs/scale.md, "A state that cannot be
// stepped").
#pragma once

#include <stdexcept>

namespace particles {

// Thrown by World::step. The world is then as the failed step left it (this
// step's forces applied, nothing moved): build it again or reset() it
// before stepping on.
class StepError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace particles
