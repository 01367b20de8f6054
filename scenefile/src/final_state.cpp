#include <charconv>
#include <cmath>

#include "particles/scene_output.h"

namespace particles {

namespace {

// Built as ordered_json so that the printed keys keep the documented order.
nlohmann::ordered_json finalState(const World& world) {
  nlohmann::ordered_json balls = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < world.ballCount(); ++i) {
    const BallState b = world.ball(i);
    balls.push_back({{"position", {b.position.x(), b.position.y()}},
                     {"velocity", {b.velocity.x(), b.velocity.y()}},
                     {"angle", b.angle},
                     {"angular_velocity", b.angularVelocity}});
  }
  nlohmann::ordered_json state;
  state["time"] = world.time();
  state["balls"] = std::move(balls);
  return state;
}

}  // namespace

nlohmann::json finalStateJson(const World& world) {
  return finalState(world);
}

std::string finalStateText(const World& world) {
  return finalState(world).dump();
}

bool allFinite(const World& world) {
  for (std::size_t i = 0; i < world.ballCount(); ++i) {
    const BallState b = world.ball(i);
    if (!b.position.allFinite() || !b.velocity.allFinite() || !std::isfinite(b.angle) ||
        !std::isfinite(b.angularVelocity))
      return false;
  }
  return true;
}

std::string formatDouble(double value) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, result.ptr);
}

}  // namespace particles
