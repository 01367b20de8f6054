#include "particles/state_hash.h"

#include <bit>
#include <cmath>
#include <cstdio>

namespace particles {
namespace {

void addBall(StateHasher& h, const BallState& b) {
  h.addDouble(b.position.x());
  h.addDouble(b.position.y());
  h.addDouble(b.velocity.x());
  h.addDouble(b.velocity.y());
  h.addDouble(b.angle);
  h.addDouble(b.angularVelocity);
}

}  // namespace

void StateHasher::addDouble(double value) {
  if (value == 0.0) value = 0.0;  // -0.0 == 0.0: both become +0.0
  std::uint64_t bits = std::bit_cast<std::uint64_t>(value);
  if (!std::isfinite(value)) bits = 0x7ff8000000000000ULL;
  addU64(bits);
}

std::uint64_t stateHash(std::span<const BallState> balls) {
  StateHasher h;
  for (const BallState& b : balls) addBall(h, b);
  return h.value();
}

std::uint64_t stateHash(const World& world) {
  StateHasher h;
  for (std::size_t i = 0; i < world.ballCount(); ++i) addBall(h, world.ball(i));
  return h.value();
}

std::string hashHex(std::uint64_t hash) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(hash));
  return buf;
}

}  // namespace particles
