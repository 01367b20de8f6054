#include "particles/timestep/stepper.h"

#include "particles/reference/box2d_world.h"

namespace particles::timestep {
namespace {

class EngineStepper : public Stepper {
 public:
  explicit EngineStepper(const SceneDef& scene) : world_(scene) {}
  void step() override { world_.step(); }
  double time() const override { return world_.time(); }
  std::size_t ballCount() const override { return world_.ballCount(); }
  BallState ball(std::size_t i) const override { return world_.ball(i); }

 private:
  World world_;
};

class Box2DStepper : public Stepper {
 public:
  Box2DStepper(const SceneDef& scene, const reference::Box2DSettings& settings)
      : world_(scene, settings) {}
  void step() override { world_.step(); }
  double time() const override { return world_.time(); }
  std::size_t ballCount() const override { return world_.ballCount(); }
  BallState ball(std::size_t i) const override { return world_.ball(i); }

 private:
  reference::Box2DWorld world_;
};

}  // namespace

std::unique_ptr<Stepper> engineStepper(const SceneDef& scene) {
  return std::make_unique<EngineStepper>(scene);
}

std::unique_ptr<Stepper> box2dStepper(const SceneDef& scene,
                                      const reference::Box2DSettings& settings) {
  return std::make_unique<Box2DStepper>(scene, settings);
}

}  // namespace particles::timestep
