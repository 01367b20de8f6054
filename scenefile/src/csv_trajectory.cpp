#include <charconv>

#include "particles/scene_output.h"

namespace particles {
namespace {

void append(std::string& line, double value) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, value);  // shortest round-trip
  line.append(buf, result.ptr);
}

}  // namespace

CsvTrajectoryWriter::CsvTrajectoryWriter(std::ostream& out) : out_(out) {
  out_ << "t,id,x,y,angle,vx,vy,omega\n";
}

void CsvTrajectoryWriter::write(const World& world) {
  const double t = world.time();
  for (std::size_t i = 0; i < world.ballCount(); ++i) writeRow(t, i, world.ball(i));
}

void CsvTrajectoryWriter::write(double time, std::span<const BallState> balls) {
  for (std::size_t i = 0; i < balls.size(); ++i) writeRow(time, i, balls[i]);
}

void CsvTrajectoryWriter::writeRow(double time, std::size_t id, const BallState& b) {
  line_.clear();
  append(line_, time);
  line_ += ',';
  line_ += std::to_string(id);
  for (double x : {b.position.x(), b.position.y(), b.angle, b.velocity.x(), b.velocity.y(),
                   b.angularVelocity}) {
    line_ += ',';
    append(line_, x);
  }
  line_ += '\n';
  out_ << line_;
}

}  // namespace particles
