#include "particles/viewer/session.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace particles::viewer {
namespace {

// Rounding slack of the accumulator, in steps: 60 frames of 1/60 s at
// dt = 1e-3 must make exactly 1000 steps, not 999 and a remainder of
// 0.99999999999.
constexpr double kAccumulatorSlack = 1e-9;

SceneDef withPulls(const SceneDef& scene) {
  SceneDef s = scene;
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    ForceDef pull;
    pull.type = ForceType::Pull;
    pull.ball = static_cast<int>(i);
    pull.target = scene.balls[i].position;
    pull.stiffness = kPullStiffnessPerKg * scene.balls[i].mass;
    s.forces.push_back(pull);  // start 0, end infinity: always active
  }
  return s;
}

}  // namespace

Session::Session(const SceneDef& scene)
    : scene_(scene),
      withPull_(withPulls(scene)),
      pullBase_(scene.forces.size()),
      engine_(withPull_),
      viewBounds_(runBounds(scene)) {
  engine_.recordImpacts(true);
  try {
    box2d_ = std::make_unique<reference::Box2DWorld>(withPull_,
                                                     reference::Box2DSettings::forScene(withPull_));
  } catch (const std::invalid_argument& e) {
    box2dError_ = e.what();
  }
}

std::vector<BallState> Session::engineBalls() const {
  std::vector<BallState> balls;
  balls.reserve(engine_.ballCount());
  for (std::size_t i = 0; i < engine_.ballCount(); ++i) balls.push_back(engine_.ball(i));
  return balls;
}

std::vector<BallState> Session::box2dBalls() const {
  std::vector<BallState> balls;
  if (!box2d_) return balls;
  balls.reserve(box2d_->ballCount());
  for (std::size_t i = 0; i < box2d_->ballCount(); ++i) balls.push_back(box2d_->ball(i));
  return balls;
}

long long Session::advance(double frameSeconds) {
  if (paused_ || !(frameSeconds > 0.0)) return 0;
  accumulator_ += frameSeconds * timeScale() / engine_.dt();
  const long long steps = static_cast<long long>(std::floor(accumulator_ + kAccumulatorSlack));
  accumulator_ = std::max(0.0, accumulator_ - static_cast<double>(steps));
  if (steps > 0) clearImpacts();
  for (long long s = 0; s < steps; ++s) step();
  return steps;
}

void Session::stepOnce() {
  clearImpacts();
  step();
}

void Session::restart() {
  engine_.reset(withPull_);
  if (box2d_) box2d_->reset(withPull_);
  accumulator_ = 0.0;
  held_.reset();
  clearImpacts();
}

double Session::timeScale() const {
  return std::ldexp(1.0, timeScaleLog2_);
}

void Session::faster() {
  timeScaleLog2_ = std::min(timeScaleLog2_ + 1, kMaxTimeScaleLog2);
}

void Session::slower() {
  timeScaleLog2_ = std::max(timeScaleLog2_ - 1, kMinTimeScaleLog2);
}

void Session::hold(int ball, const Vec2& target) {
  if (ball < 0 || static_cast<std::size_t>(ball) >= scene_.balls.size())
    throw std::out_of_range("Session::hold: no ball " + std::to_string(ball));
  held_ = ball;
  holdTarget_ = target;
}

void Session::moveHold(const Vec2& target) {
  holdTarget_ = target;
}

void Session::release() {
  held_.reset();
}

double Session::pullStiffness(int ball) const {
  return withPull_.forces.at(pullBase_ + static_cast<std::size_t>(ball)).stiffness;
}

// Each world's own pulls aim at its own balls: a free ball's target is its
// centre in that world, so its pull is exactly zero there.
void Session::aimPulls() {
  for (std::size_t i = 0; i < scene_.balls.size(); ++i) {
    const bool isHeld = held_ && static_cast<std::size_t>(*held_) == i;
    engine_.setPullTarget(pullBase_ + i, isHeld ? holdTarget_ : engine_.ball(i).position);
    if (box2d_)
      box2d_->setPullTarget(pullBase_ + i, isHeld ? holdTarget_ : box2d_->ball(i).position);
  }
}

// One step of both worlds. The engine's impacts of a frame's steps are
// merged per contact (impulses summed, the latest normal kept), so a resting
// contact shows one arrow, not one per step.
void Session::step() {
  aimPulls();
  engine_.step();
  if (box2d_) box2d_->step();
  for (const ImpactEvent& e : engine_.impacts()) {
    const std::uint64_t key = (static_cast<std::uint64_t>(e.a) << 33) |
                              (static_cast<std::uint64_t>(static_cast<std::uint32_t>(e.b)) << 1) |
                              (e.wall ? 1u : 0u);
    const auto [it, added] = impactIndex_.try_emplace(key, impacts_.size());
    if (added) {
      impacts_.push_back(e);
      continue;
    }
    ImpactEvent& merged = impacts_[it->second];
    merged.normal = e.normal;
    merged.normalImpulse += e.normalImpulse;
    merged.tangentImpulse += e.tangentImpulse;
    merged.frictionBound += e.frictionBound;
  }
}

void Session::clearImpacts() {
  impacts_.clear();
  impactIndex_.clear();
}

std::optional<int> pickBall(const std::vector<BallState>& balls, const SceneDef& scene,
                            const Vec2& point) {
  for (std::size_t i = balls.size(); i-- > 0;) {
    if (i >= scene.balls.size()) continue;
    if ((balls[i].position - point).norm() <= scene.balls[i].radius) return static_cast<int>(i);
  }
  return std::nullopt;
}

}  // namespace particles::viewer
