// One interface over everything that advances a scene in fixed steps: the
// engine's World, the Box2D twin, and a recorded trajectory (for testing the
// metrics on hand-built motion). Metrics read balls through it only, so the
// same metric code judges both engines.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "particles/reference/box2d_settings.h"
#include "particles/scene.h"
#include "particles/world.h"

namespace particles::timestep {

class Stepper {
 public:
  virtual ~Stepper() = default;
  virtual void step() = 0;
  virtual double time() const = 0;  // s, since the start
  virtual std::size_t ballCount() const = 0;
  virtual BallState ball(std::size_t i) const = 0;
};

// The engine's World for `scene` (its dt and solver settings).
std::unique_ptr<Stepper> engineStepper(const SceneDef& scene);
// The Box2D twin of `scene`, stepped with `settings` (settings.dt is its step).
std::unique_ptr<Stepper> box2dStepper(const SceneDef& scene,
                                      const reference::Box2DSettings& settings);

// A trajectory given sample by sample: frame 0 is the start, step() moves to
// the next frame. For tests: a metric fed a motion with a known error.
struct Frame {
  double time = 0.0;  // s
  std::vector<BallState> balls;
};
class RecordedStepper : public Stepper {
 public:
  explicit RecordedStepper(std::vector<Frame> frames) : frames_(std::move(frames)) {}
  void step() override {
    if (index_ + 1 < frames_.size()) ++index_;
  }
  double time() const override { return frames_[index_].time; }
  std::size_t ballCount() const override { return frames_[index_].balls.size(); }
  BallState ball(std::size_t i) const override { return frames_[index_].balls[i]; }
  std::size_t frameCount() const { return frames_.size(); }

 private:
  std::vector<Frame> frames_;
  std::size_t index_ = 0;
};

}  // namespace particles::timestep
