#include <charconv>
#include <cmath>
#include <vector>

#include "particles/scene_output.h"

namespace particles {

namespace {

// Built as ordered_json so that the printed keys keep the documented order.
nlohmann::ordered_json finalState(double time, std::span<const BallState> states) {
  nlohmann::ordered_json balls = nlohmann::ordered_json::array();
  for (const BallState& b : states) {
    balls.push_back({{"position", {b.position.x(), b.position.y()}},
                     {"velocity", {b.velocity.x(), b.velocity.y()}},
                     {"angle", b.angle},
                     {"angular_velocity", b.angularVelocity}});
  }
  nlohmann::ordered_json state;
  state["time"] = time;
  state["balls"] = std::move(balls);
  return state;
}

bool finite(const BallState& b) {
  return b.position.allFinite() && b.velocity.allFinite() && std::isfinite(b.angle) &&
         std::isfinite(b.angularVelocity);
}

}  // namespace

nlohmann::json finalStateJson(const World& world) {
  return finalState(world.time(), world.balls());
}

std::string finalStateText(const World& world) {
  return finalState(world.time(), world.balls()).dump();
}

nlohmann::json finalStateJson(double time, std::span<const BallState> balls) {
  return finalState(time, balls);
}

std::string finalStateText(double time, std::span<const BallState> balls) {
  return finalState(time, balls).dump();
}

bool allFinite(const World& world) {
  for (std::size_t i = 0; i < world.ballCount(); ++i)
    if (!finite(world.ball(i))) return false;
  return true;
}

bool allFinite(std::span<const BallState> balls) {
  for (const BallState& b : balls)
    if (!finite(b)) return false;
  return true;
}

std::string formatDouble(double value) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, result.ptr);
}

}  // namespace particles
