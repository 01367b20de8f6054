// What `particles run` writes: the final state as JSON and the trajectory as
// CSV. Both are deterministic: the same world gives the same bytes.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <span>
#include <string>

#include "particles/world.h"

namespace particles {

// {"time": T, "balls": [{"position": [x, y], "velocity": [vx, vy],
//  "angle": a, "angular_velocity": w}, ...]}, balls in the scene's order.
// (nlohmann::json keeps object keys sorted, so its dump() prints them
// alphabetically; finalStateText keeps the order above.)
nlohmann::json finalStateJson(const World& world);

// What `particles run` prints: the same object on one line, keys in the
// order above, numbers as nlohmann prints them (shortest round-trip).
std::string finalStateText(const World& world);

// The same for a state read from elsewhere (the Box2D twin): `time` in s and
// the balls in the scene's order. Same keys, order and number format.
nlohmann::json finalStateJson(double time, std::span<const BallState> balls);
std::string finalStateText(double time, std::span<const BallState> balls);

// True when every position, velocity, angle and angular velocity is finite.
bool allFinite(const World& world);
bool allFinite(std::span<const BallState> balls);

// Shortest decimal text that reads back as exactly the same double
// (std::to_chars), independent of the locale.
std::string formatDouble(double value);

// The trajectory as CSV: the header "t,id,x,y,angle,vx,vy,omega", then one
// row per ball for each call of write(), numbers at full round-trip precision.
class CsvTrajectoryWriter {
 public:
  explicit CsvTrajectoryWriter(std::ostream& out);  // writes the header
  void write(const World& world);                   // rows at world.time()
  // Rows for a state read from elsewhere (the Box2D twin), at `time` (s).
  void write(double time, std::span<const BallState> balls);

 private:
  void writeRow(double time, std::size_t id, const BallState& b);

  std::ostream& out_;
  std::string line_;  // reused buffer
};

}  // namespace particles
