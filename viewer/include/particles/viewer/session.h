// What the viewer runs: the engine's World and its Box2D twin, stepped
// together with a fixed time step from an accumulator, plus the mouse pull.
// No drawing and no SFML here: the display never changes the physics, and the
// tests drive a Session exactly as the window does.
//
// The mouse pull is the handout's F = k (M - O), a ForceDef of type Pull. A
// World copies its scene and only lets a pull's target change afterwards
// (World::setPullTarget), so the session adds one always-active pull per ball
// to its copy of the scene, after the scene's own forces, with
// k = kPullStiffnessPerKg * mass. A ball that is not held has its pull's
// target set to its own centre before every step, so its force is exactly
// zero (x - x == 0 in floating point) and the run is bit-identical to the
// scene without those forces; the held ball's target is the cursor.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "particles/reference/box2d_world.h"
#include "particles/viewer/camera.h"
#include "particles/world.h"

namespace particles::viewer {

// N/m per kg of the held ball: k = 50 m, so a held ball oscillates about the
// cursor at sqrt(k/m) = 7.1 rad/s (period 0.89 s) whatever its mass.
inline constexpr double kPullStiffnessPerKg = 50.0;

// Time scales that + and - step through: a power of two from 1/16 to 16.
inline constexpr int kMinTimeScaleLog2 = -4;
inline constexpr int kMaxTimeScaleLog2 = 4;

class Session {
 public:
  // Builds both worlds. When Box2D cannot represent the scene the session
  // runs the engine alone (hasBox2D() false, box2dError() says why).
  explicit Session(const SceneDef& scene);

  const SceneDef& scene() const { return scene_; }  // as loaded, without the pulls
  // What the camera fits: runBounds of the scene, computed once.
  const Bounds& viewBounds() const { return viewBounds_; }
  const World& engine() const { return engine_; }
  bool hasBox2D() const { return box2d_ != nullptr; }
  const reference::Box2DWorld* box2d() const { return box2d_.get(); }
  const std::string& box2dError() const { return box2dError_; }
  std::vector<BallState> engineBalls() const;
  std::vector<BallState> box2dBalls() const;  // empty without a twin

  // Adds frameSeconds (s, real time) times the time scale to the accumulator
  // and runs as many whole steps of dt as it holds; nothing while paused.
  // Returns the steps run.
  long long advance(double frameSeconds);
  // One step of dt now, paused or not (key O).
  void stepOnce();
  // Both worlds back to the scene's start; the pull is released (key R).
  void restart();

  bool paused() const { return paused_; }
  void setPaused(bool paused) { paused_ = paused; }

  // Simulated seconds per real second: 2^timeScaleLog2(). It changes how
  // many steps a frame runs, never dt.
  int timeScaleLog2() const { return timeScaleLog2_; }
  double timeScale() const;
  void faster();
  void slower();

  // The mouse pull on ball `ball` toward `target` (m), until release().
  void hold(int ball, const Vec2& target);
  void moveHold(const Vec2& target);
  void release();
  std::optional<int> held() const { return held_; }
  const Vec2& holdTarget() const { return holdTarget_; }
  // N/m, the stiffness of ball i's pull.
  double pullStiffness(int ball) const;

  // The engine's impacts in the steps since the last call of advance() or
  // stepOnce() that ran a step (kept while paused), for key D.
  const std::vector<ImpactEvent>& impacts() const { return impacts_; }

 private:
  void step();
  void aimPulls();
  void clearImpacts();

  SceneDef scene_;     // as loaded
  SceneDef withPull_;  // plus one pull per ball, from index pullBase_
  std::size_t pullBase_ = 0;
  World engine_;
  std::unique_ptr<reference::Box2DWorld> box2d_;
  std::string box2dError_;
  Bounds viewBounds_;

  double accumulator_ = 0.0;  // steps owed, in units of dt, in [0, 1) after advance()
  bool paused_ = false;
  int timeScaleLog2_ = 0;
  std::optional<int> held_;
  Vec2 holdTarget_{0.0, 0.0};
  std::vector<ImpactEvent> impacts_;
  std::unordered_map<std::uint64_t, std::size_t> impactIndex_;  // (a, b, wall) -> impacts_ index
};

// The ball under `point` (m): the last one in drawing order whose disk
// contains it, so the ball drawn on top wins. balls[i] is scene.balls[i]'s
// state (radius from the scene).
std::optional<int> pickBall(const std::vector<BallState>& balls, const SceneDef& scene,
                            const Vec2& point);

}  // namespace particles::viewer
