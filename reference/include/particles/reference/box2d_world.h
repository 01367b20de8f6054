// The Box2D twin of a scene: a b2World with the same balls, walls, materials,
// gravity and forces as a SceneDef, stepped with Box2D's own solver so the
// engine's results can be compared with it. How each part of a scene maps to
// Box2D, and why, is in docs/box2d-twin.md.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "particles/reference/box2d_inspect.h"
#include "particles/reference/box2d_settings.h"
#include "particles/scene.h"
#include "particles/world.h"

namespace particles::reference {

// Steps in which some ball ran into one of Box2D's per-step motion clamps:
// Box2D then scales the velocity down so that the step moves it exactly
// b2_maxTranslation (2 m) or turns it b2_maxRotation (pi/2), which the engine
// never does. Counted in the discrete step only (not in continuous sub-steps).
struct Box2DLimitHits {
  long long translation = 0;  // steps with some |v| dt at b2_maxTranslation
  long long rotation = 0;     // steps with some |w| dt at b2_maxRotation
};

class Box2DWorld {
 public:
  // Throws std::invalid_argument for a scene Box2D cannot represent at all
  // (dt <= 0, a ball with mass, inertia or radius <= 0, a force on a missing
  // ball). Scenes that Box2D represents poorly are checkBox2DRange's job.
  Box2DWorld(const SceneDef& scene, const Box2DSettings& settings);
  ~Box2DWorld();
  // A moved-from Box2DWorld may only be destroyed or assigned to.
  Box2DWorld(Box2DWorld&&) noexcept;
  Box2DWorld& operator=(Box2DWorld&&) noexcept;
  Box2DWorld(const Box2DWorld&) = delete;
  Box2DWorld& operator=(const Box2DWorld&) = delete;

  // Rebuilds the world for another scene (any ball and wall counts), keeping
  // the settings. Bit-identical to a freshly constructed Box2DWorld: the
  // b2World is destroyed and constructed again in the same storage, so no
  // contact, warm-starting impulse or broad-phase state survives; what is
  // saved is the allocation of the b2World (~100 kB) and of this object.
  void reset(const SceneDef& scene);

  // Applies this step's forces, then one b2World::Step of settings().dt.
  void step();
  void run(long long steps);

  double time() const;  // s, stepIndex() * settings().dt
  long long stepIndex() const;
  std::size_t ballCount() const;
  std::size_t wallCount() const;
  // A ball's state in the scene's ball order, Box2D's floats widened.
  BallState ball(std::size_t i) const;
  // Every ball's state, in the scene's order (as World::balls).
  std::vector<BallState> balls() const;
  const Box2DSettings& settings() const;
  const Box2DLimitHits& limitHits() const;

  // Replaces the target of pull force `force` (index into SceneDef::forces).
  void setPullTarget(std::size_t force, const Vec2& target);

  // Inspection of the Box2D objects (box2d_inspect.h), for tests.
  BodyInfo bodyInfo(std::size_t ball) const;
  WallInfo wallInfo(std::size_t wall) const;
  std::vector<ContactInfo> contacts() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace particles::reference
